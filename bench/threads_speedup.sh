#!/bin/bash
# Threads and the single-thread cost, side by side: for each round and case, `bench --runs 3` of
# OLD (one thread), then NEW with --threads 1, then NEW with --threads 2; prints the ratios.
# Usage: bench/threads_speedup.sh OLD_BINARY NEW_BINARY [ROUNDS=3] [CASES="a c"]
# (docs/performance.md, Threads; a DP case such as d takes about a minute per run)
set -eu
OLD=$1 NEW=$2 R=${3:-3} CASES=${4:-"a c"}
median() { "$@" | grep -oE 'median [0-9.e+]+' | cut -d' ' -f2; }
for r in $(seq 1 "$R"); do
  for c in $CASES; do
    o=$(median "$OLD" bench --case "$c" --runs 3)
    t1=$(median "$NEW" bench --case "$c" --runs 3 --threads 1)
    t2=$(median "$NEW" bench --case "$c" --runs 3 --threads 2)
    echo "round $r case $c: old $o  T=1 $t1  T=2 $t2  T1/old $(awk -v a="$t1" -v b="$o" 'BEGIN{printf "%.3f", a/b}')  T2/T1 $(awk -v a="$t2" -v b="$t1" 'BEGIN{printf "%.2f", a/b}')"
  done
done
