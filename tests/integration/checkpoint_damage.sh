#!/usr/bin/env bash
# A damaged checkpoint never yields a result that was not simulated: one byte of a checkpoint
# changed (anywhere in the file: data, attributes, HDF5's own structures) and the run that
# continues it gives the result of a run from the start, bit for bit. Either the damage is seen
# (HDF5 checksums: the 1.10 format's headers and indexes, Fletcher-32 over every dataset) and
# the checkpoint is not used, or the byte was one that nothing reads. Before 2026-12-07 a byte
# changed in a particle's position or in the exit record was read as it stood and the run went
# on from a state that never happened. SP and smooth DP (its vertices are the model's own data).
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sp_a.json" <<'JOB'
{"N": 200, "W": 15, "w": 5, "zeta": 1, "mu": 0,
 "run": {"t_max": 20, "target_rel_err": 1e-9, "min_window": 5, "min_transient": 2, "rate_bin": 0.5, "checkpoint_interval": 20}}
JOB
cat > "$WORK/dp_a.json" <<'JOB'
{"model": "dp_smooth", "N": 40, "W": 8, "w": 3, "E_w": 100, "dp": {"E_c": 100}, "zeta": 0.3, "mu": 1.0,
 "run": {"t_max": 2, "target_rel_err": 1e-9, "min_window": 1, "min_transient": 0.5, "rate_bin": 0.1,
         "check_interval": 0.5, "checkpoint_interval": 1}}
JOB
# b: the same trajectory run longer, which continues a's final checkpoint (simulate --continue-from)
for m in sp dp; do
  python3 - "$WORK/${m}_a.json" "$WORK/${m}_b.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j["run"]["t_max"] *= 2
json.dump(j, open(sys.argv[2], "w"))
PY
done
for m in sp dp; do
  flips=$([ $m = sp ] && echo 40 || echo 20)  # a DP run costs more
  "$BIN" simulate "$WORK/${m}_a.json" -o "$WORK/${m}_a" --progress quiet > /dev/null 2> "$WORK/log" || fail "$m: a failed: $(tail -1 "$WORK/log")"
  "$BIN" simulate "$WORK/${m}_b.json" -o "$WORK/${m}_fresh" --progress quiet > /dev/null 2>&1 || fail "$m: b failed"
  "$BIN" simulate "$WORK/${m}_b.json" -o "$WORK/${m}_cont" --continue-from "$WORK/${m}_a/checkpoint.h5" --progress log \
    > /dev/null 2> "$WORK/log" || fail "$m: b continued failed"
  grep -q "continued the run of" "$WORK/log" || fail "$m: an intact checkpoint was not continued: $(tail -2 "$WORK/log")"
  reference=$(result_data "$WORK/${m}_fresh/result.h5")
  [ "$(result_data "$WORK/${m}_cont/result.h5")" = "$reference" ] || fail "$m: continuing an intact checkpoint changed the result"
  size=$(stat -c %s "$WORK/${m}_a/checkpoint.h5")
  refused=0
  # every byte position is fair: evenly spread over the file, then random ones
  RANDOM=7
  for i in $(seq 0 $((flips - 1))); do
    if [ "$i" -lt $((flips / 2)) ]; then pos=$((i * size / (flips / 2))); else pos=$(( (RANDOM * 32768 + RANDOM) % size )); fi
    cp "$WORK/${m}_a/checkpoint.h5" "$WORK/damaged.h5"
    python3 -c "
import sys
p, at = sys.argv[1], int(sys.argv[2])
with open(p, 'r+b') as f:
    f.seek(at); b = f.read(1); f.seek(at); f.write(bytes([b[0] ^ 0xFF]))" "$WORK/damaged.h5" "$pos"
    rm -rf "$WORK/out"
    set +e
    "$BIN" simulate "$WORK/${m}_b.json" -o "$WORK/out" --continue-from "$WORK/damaged.h5" --progress log > /dev/null 2> "$WORK/log"
    rc=$?
    set -e
    [ "$rc" -eq 0 ] || fail "$m: byte $pos of $size changed: simulate ended with $rc: $(tail -1 "$WORK/log")"
    grep -q "not continuing" "$WORK/log" && refused=$((refused + 1))
    [ "$(result_data "$WORK/out/result.h5")" = "$reference" ] ||
      fail "$m: byte $pos of $size changed: the checkpoint was continued and the result differs from a run from the start"
  done
  echo "ok  $m: $flips checkpoints with one byte changed (of $size): $refused seen as damaged, the rest harmless; every result bit-identical"
done
