#!/usr/bin/env bash
# Configure and build beverloo in ./build (Release). Usage: scripts/build.sh [main|all] [extra cmake args]
#   main: the beverloo binary only (no tests: the main job's first run)
#   all (default): everything, the test suite included
set -euo pipefail
cd "$(dirname "$0")/.."
MODE=all
case "${1:-}" in main|all) MODE=$1; shift ;; esac
if [ "$MODE" = main ]; then
  # a build tree configured with the tests keeps them; a fresh one leaves them out
  TESTS=$( [ -f build/CMakeCache.txt ] && grep -q '^BEVERLOO_BUILD_TESTS:BOOL=ON' build/CMakeCache.txt && echo ON || echo OFF )
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBEVERLOO_BUILD_TESTS="$TESTS" "$@" >/dev/null
  cmake --build build -j "$(nproc)" --target beverloo
else
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBEVERLOO_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build build -j "$(nproc)"
fi
