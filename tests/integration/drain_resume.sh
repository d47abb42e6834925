#!/usr/bin/env bash
# A draining hopper (reinject = false) stopped part-way (SIGTERM: checkpoint, exit 5; SIGKILL
# after a checkpoint) and resumed gives the result of an uninterrupted run, bit for bit: the
# checkpoint holds only the particles (DP: polygons) still in the hopper. SP in a 45/0 hopper
# and smooth DP in a 45/45 one.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sp.json" <<'JOB'
{"dimension": 2, "N": 600, "W": 40, "w": 4, "theta_w_left_deg": 45, "theta_w_right_deg": 0, "E_sp": 100,
 "zeta": 0.316, "mu": 0, "reinject": false, "seed": 11, "run": {"t_max": 1000, "checkpoint_interval": 2}}
JOB
cat > "$WORK/dp.json" <<'JOB'
{"model": "dp_smooth", "N": 40, "W": 12, "w": 3, "theta_w_deg": 45, "E_w": 100, "dp": {"E_c": 115.7, "contact_width": 0.2},
 "zeta": 0.316, "mu": 0, "reinject": false, "drain": {"fit_skip": 3, "block_exits": 4}, "seed": 4,
 "run": {"t_max": 200, "checkpoint_interval": 1}}
JOB
drain_data() { result_data "$1"; h5dump -m %.17g -g /drain "$1" | tail -n +2; }
for job in sp dp; do
  start=$(date +%s.%N)
  "$BIN" simulate "$WORK/$job.json" -o "$WORK/$job.clean" --progress quiet > /dev/null
  took=$(echo "$(date +%s.%N) - $start" | bc)
  grep -q '"status": "drained"' "$WORK/$job.clean/summary.json" || fail "$job: the clean run did not drain"
  # SIGTERM part-way: a checkpoint of the half-drained hopper, exit 5, then resume
  "$BIN" simulate "$WORK/$job.json" -o "$WORK/$job.term" --progress quiet > /dev/null 2>&1 &
  pid=$!
  sleep "$(echo "$took * 0.5" | bc -l)"
  kill -TERM "$pid" 2>/dev/null || fail "$job: the run ended before SIGTERM; make it longer"
  set +e; wait "$pid"; rc=$?; set -e
  [ "$rc" -eq 5 ] || fail "$job: SIGTERM gave exit $rc, expected 5"
  "$BIN" simulate "$WORK/$job.json" -o "$WORK/$job.term" --resume --progress quiet > /dev/null
  diff <(drain_data "$WORK/$job.clean/result.h5") <(drain_data "$WORK/$job.term/result.h5") > "$WORK/diff" \
    || { head -20 "$WORK/diff"; fail "$job: the drain resumed after SIGTERM differs from the uninterrupted one"; }
  # SIGKILL once a checkpoint exists, then resume
  "$BIN" simulate "$WORK/$job.json" -o "$WORK/$job.kill" --progress quiet > /dev/null 2>&1 &
  pid=$!
  for _ in $(seq 600); do [ -f "$WORK/$job.kill/checkpoint.h5" ] && break; sleep 0.05; done
  sleep "$(echo "$took * 0.3" | bc -l)"
  kill -9 "$pid" 2>/dev/null || fail "$job: the run ended before SIGKILL"
  wait "$pid" 2>/dev/null || true
  "$BIN" simulate "$WORK/$job.json" -o "$WORK/$job.kill" --resume --progress quiet > /dev/null
  diff <(drain_data "$WORK/$job.clean/result.h5") <(drain_data "$WORK/$job.kill/result.h5") > /dev/null \
    || fail "$job: the drain resumed after SIGKILL differs from the uninterrupted one"
  echo "ok  $job drain: SIGTERM and SIGKILL + resume give the uninterrupted result bit for bit"
done
