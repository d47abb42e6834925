#!/usr/bin/env bash
# README's test command: install what is missing, build, run the default test suite (unit + physics
# + integration; the long validations carry the label "validation" and the fuzzing pass the label
# "fuzz": both are run by hand and excluded here).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" -LE 'validation|fuzz' --timeout 900
