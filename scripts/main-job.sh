#!/usr/bin/env bash
# README's main-job command: install what is missing, build, run the quickstart campaign
# (14 hopper flows, 2D SP with the authors' model, both dissipation limits; 48 s on 2 cores), which ends with
# the fits and the report in campaigns/quickstart/report/index.html; then show Q(w) and the fits.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh main
scripts/build.sh main
BIN=./build/cli/beverloo
"$BIN" run sweeps/quickstart.json --dir campaigns/quickstart
"$BIN" campaign status --dir campaigns/quickstart
"$BIN" query campaigns/quickstart \
  "SELECT CASE WHEN mu = 0 THEN 'drag only' ELSE 'friction only' END AS limit_, w, status, round(Q, 4) AS Q, round(Q_err, 4) AS Q_err FROM runs ORDER BY mu, w"
"$BIN" query campaigns/quickstart "SELECT label, points, round(beta, 3) AS beta, round(beta_err, 3) AS beta_err, round(k, 2) AS k, round(C, 4) AS C, round(chi2_red, 2) AS chi2_red FROM beverloo_fits"
