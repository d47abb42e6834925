#!/bin/bash
# Speed of two beverloo binaries side by side: alternating runs of `bench --runs 1` of OLD and
# NEW, both pinned to core 0 (this machine's two cores differ in speed; docs/performance.md),
# and per case the median and range over the pairs of the ratio new/old.
# Usage: bench/alternate_pinned.sh OLD_BINARY NEW_BINARY PAIRS CASE...   e.g. ... 5 a b c
set -euo pipefail
OLD=$1 NEW=$2 PAIRS=$3
shift 3
args=()
for c in "$@"; do args+=(--case "$c"); done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
for p in $(seq 1 "$PAIRS"); do
  taskset -c 0 "$OLD" bench "${args[@]}" --runs 1 --json "$WORK/old_$p.json" > /dev/null
  taskset -c 0 "$NEW" bench "${args[@]}" --runs 1 --json "$WORK/new_$p.json" > /dev/null
done
python3 - "$WORK" "$PAIRS" <<'PY'
import json, statistics, sys
work, pairs = sys.argv[1], int(sys.argv[2])
ratios = {}
for p in range(1, pairs + 1):
    old = {c["id"]: c["median"] for c in json.load(open(f"{work}/old_{p}.json"))["cases"]}
    new = {c["id"]: c["median"] for c in json.load(open(f"{work}/new_{p}.json"))["cases"]}
    for k in old:
        ratios.setdefault(k, []).append(new[k] / old[k])
for k, v in ratios.items():
    print(f"{k}  new/old median {statistics.median(v):.3f}  range {min(v):.3f}-{max(v):.3f}  ({len(v)} pairs)")
PY
