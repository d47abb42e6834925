#!/usr/bin/env bash
# README's main-job command: install what is missing, build, run the example hopper flow.
# (Until the campaign service lands this is one `beverloo simulate` run of about a minute or less.)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec ./build/orchestrator/beverloo simulate examples/drag_only_2d.json -o out/drag_only_2d --overwrite
