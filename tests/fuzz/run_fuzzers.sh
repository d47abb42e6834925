#!/usr/bin/env bash
# The fuzzing pass of the job-, sweep- and data-file readers (issue 15): builds build-fuzz/ with
# clang, AddressSanitizer, UBSan and libFuzzer (BEVERLOO_FUZZ=ON), seeds each fuzzer with the
# shipped files and the hostile corpus, and runs each for SECONDS (default 120). A crash, a
# sanitizer report, a leak, a timeout (-timeout=10) or memory over 2 GiB stops that fuzzer and
# leaves the input in build-fuzz/findings/<fuzzer>/. Exit 1 if any fuzzer found something.
# Usage: tests/fuzz/run_fuzzers.sh [SECONDS]     (ctest -L fuzz runs it with 60)
set -euo pipefail
cd "$(dirname "$0")/../.."
SECONDS_EACH=${1:-120}
command -v clang++ > /dev/null || { echo "run_fuzzers: clang++ is needed (Debian's clang)"; exit 1; }
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DBEVERLOO_FUZZ=ON > /dev/null
cmake --build build-fuzz --target fuzz_job_file fuzz_sweep_file fuzz_experiment_csv > build-fuzz/build.log 2>&1 \
  || { tail -30 build-fuzz/build.log; exit 1; }
found=0
for fuzzer in fuzz_job_file fuzz_sweep_file fuzz_experiment_csv; do
  corpus=build-fuzz/corpus/$fuzzer findings=build-fuzz/findings/$fuzzer
  rm -rf "$findings"; mkdir -p "$corpus" "$findings"
  case $fuzzer in
    fuzz_job_file) cp examples/*.json tests/data/hostile/inputs/job_*.json "$corpus"/ 2>/dev/null || true ;;
    fuzz_sweep_file) cp sweeps/*.json tests/data/bad_sweeps/*.json tests/data/hostile/inputs/sweep_*.json "$corpus"/ ;;
    fuzz_experiment_csv) cp tests/data/hostile/inputs/csv_*.csv "$corpus"/ ;;
  esac
  set +e
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    "build-fuzz/tests/fuzz/$fuzzer" "$corpus" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -artifact_prefix="$findings/" -print_final_stats=1 > "build-fuzz/$fuzzer.log" 2>&1
  rc=$?
  set -e
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "build-fuzz/$fuzzer.log" | grep -o '[0-9]*$' || echo "?")
  if [ "$rc" -ne 0 ] || ls "$findings"/* > /dev/null 2>&1; then
    found=1
    echo "FOUND $fuzzer: exit $rc after $runs inputs; inputs in $findings; log build-fuzz/$fuzzer.log:"
    grep -m 5 -E 'ERROR|runtime error|SUMMARY|terminate|deadly' "build-fuzz/$fuzzer.log" || true
  else
    echo "ok    $fuzzer: $runs inputs in $SECONDS_EACH s, no crash, no sanitizer report, no leak"
  fi
done
exit $found
