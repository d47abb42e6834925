#!/usr/bin/env bash
# README's main-job command: install what is missing, build, run the quickstart campaign
# (12 hopper flows, 2D SP, both dissipation limits; about a minute on 2 cores) and show Q(w).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
BIN=./build/orchestrator/beverloo
"$BIN" run sweeps/quickstart.json --dir campaigns/quickstart
"$BIN" campaign status --dir campaigns/quickstart
"$BIN" query campaigns/quickstart \
  "SELECT CASE WHEN mu = 0 THEN 'drag only' ELSE 'friction only' END AS limit_, w, status, round(Q, 4) AS Q, round(Q_err, 4) AS Q_err FROM runs ORDER BY mu, w"
