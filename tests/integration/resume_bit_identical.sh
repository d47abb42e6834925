#!/usr/bin/env bash
# SIGKILL at arbitrary moments, then --resume until done: the result equals, bit for bit, a
# run that was never interrupted. Also SIGTERM: checkpoint, exit 5, resume, same result.
# With the argument "dp": the same for a smooth DP job (the vertices are the checkpointed state).
source "$(dirname "$0")/lib.sh"
if [ "${1:-sp}" = dp ]; then
cat > "$WORK/job.json" <<'JOB'
{"model": "dp_smooth", "N": 60, "W": 8, "w": 3, "E_w": 100, "dp": {"E_c": 100}, "zeta": 0.3, "mu": 1.0,
 "run": {"t_max": 6, "target_rel_err": 1e-9, "min_window": 2, "min_transient": 1, "rate_bin": 0.2,
         "check_interval": 0.5, "checkpoint_interval": 0.3, "trajectory_every_steps": 5000}}
JOB
else
cat > "$WORK/job.json" <<'JOB'
{"dimension": 2, "N": 400, "W": 16, "w": 5, "E_sp": 100, "zeta": 0.3, "mu": 1.0,
 "run": {"t_max": 150, "target_rel_err": 1e-9, "min_window": 20, "checkpoint_interval": 3,
         "trajectory_every_steps": 5000}}
JOB
fi
start=$(date +%s.%N)
"$BIN" simulate "$WORK/job.json" -o "$WORK/clean" --progress quiet > /dev/null
took=$(echo "$(date +%s.%N) - $start" | bc)
echo "uninterrupted run: ${took}s"

# killed twice at moments scaled to this machine's speed, then resumed to the end
kills=0
last_kill_hit=0
for frac in 0.25 0.35; do
  delay=$(echo "$took * $frac" | bc -l)
  "$BIN" simulate "$WORK/job.json" -o "$WORK/killed" --resume --progress quiet > /dev/null 2>&1 &
  pid=$!
  # kill only once a checkpoint exists (a loaded machine may take longer than the delay to write one)
  for _ in $(seq 600); do [ -f "$WORK/killed/checkpoint.h5" ] && break; sleep 0.05; done
  sleep "$delay"
  if kill -9 "$pid" 2>/dev/null; then kills=$((kills + 1)); last_kill_hit=1; else last_kill_hit=0; fi
  wait "$pid" 2>/dev/null || true
done
[ "$kills" -ge 1 ] || fail "the run finished before it could be killed; make the job longer"
[ -f "$WORK/killed/checkpoint.h5" ] || fail "no checkpoint after the kills"
# a run that was killed leaves no result (one whose kill came too late finished: its result is
# checked against the clean run below like any other)
[ "$last_kill_hit" -eq 0 ] || [ ! -f "$WORK/killed/result.h5" ] || fail "a killed run left a result"
# --resume of another job over this one's checkpoint: refused (exit 2), the directory unchanged
sed 's/"w": 5,/"w": 4,/; s/"w": 3,/"w": 4,/' "$WORK/job.json" > "$WORK/other.json"
cmp -s "$WORK/job.json" "$WORK/other.json" && fail "the other job is the same job"
before=$(cat "$WORK/killed"/* | sha256sum)
set +e; "$BIN" simulate "$WORK/other.json" -o "$WORK/killed" --resume --progress quiet > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -qE "another job's run|result of a different job" "$WORK/err" \
  || fail "--resume of another job gave exit $rc: $(cat "$WORK/err")"
[ "$before" = "$(cat "$WORK/killed"/* | sha256sum)" ] || fail "a refused --resume of another job changed the directory"
"$BIN" simulate "$WORK/job.json" -o "$WORK/killed" --resume --progress quiet > /dev/null
resumed=$(h5dump -a /run/resumed_times "$WORK/killed/result.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
[ "$resumed" -ge 1 ] || fail "the final run did not resume from a checkpoint"
diff <(result_data "$WORK/clean/result.h5") <(result_data "$WORK/killed/result.h5") > "$WORK/diff" \
  || { head -40 "$WORK/diff"; fail "resumed result differs from the uninterrupted one"; }
diff <(h5dump -d /particles/all/position/step "$WORK/clean/trajectory.h5" | tail -n +2) \
     <(h5dump -d /particles/all/position/step "$WORK/killed/trajectory.h5" | tail -n +2) > /dev/null \
  || fail "trajectory frames differ after resume"
echo "ok  SIGKILL x$kills + resume ($resumed resumes): bit-identical result"

# SIGTERM: checkpoint at once, exit 5, then resume
"$BIN" simulate "$WORK/job.json" -o "$WORK/term" --progress quiet > /dev/null 2>&1 &
pid=$!
sleep "$(echo "$took * 0.4" | bc -l)"
kill -TERM "$pid"
set +e; wait "$pid"; rc=$?; set -e
[ "$rc" -eq 5 ] || fail "SIGTERM: exit $rc, expected 5"
[ -f "$WORK/term/checkpoint.h5" ] || fail "SIGTERM left no checkpoint"
"$BIN" simulate "$WORK/job.json" -o "$WORK/term" --resume --progress quiet > /dev/null
diff <(result_data "$WORK/clean/result.h5") <(result_data "$WORK/term/result.h5") > /dev/null \
  || fail "result after SIGTERM + resume differs"
echo "ok  SIGTERM: exit 5, resume: bit-identical result"
# a finished run resumed again does nothing
"$BIN" simulate "$WORK/job.json" -o "$WORK/term" --resume --progress quiet 2>&1 | grep -q "already complete" \
  || fail "resuming a finished run must say so"

# checkpoints by wall clock only (no simulated-time cadence), so at arbitrary steps: a run
# killed after some of them and resumed equals one that never wrote a checkpoint
python3 - "$WORK/job.json" "$WORK/job_wall.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j["run"]["checkpoint_interval"] = 0
json.dump(j, open(sys.argv[2], "w"))
PY
"$BIN" simulate "$WORK/job_wall.json" -o "$WORK/wall_clean" --checkpoint-wall 0 --progress quiet > /dev/null
[ ! -f "$WORK/wall_clean/checkpoint.h5" ] || fail "--checkpoint-wall 0 with checkpoint_interval 0 wrote a checkpoint"
"$BIN" simulate "$WORK/job_wall.json" -o "$WORK/wall" --checkpoint-wall 0.05 --progress quiet > /dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do [ -f "$WORK/wall/checkpoint.h5" ] && break; sleep 0.05; done
sleep "$(echo "$took * 0.3" | bc -l)"
kill -9 "$pid" 2>/dev/null || fail "the wall-clock run finished before it could be killed"
wait "$pid" 2>/dev/null || true
[ -f "$WORK/wall/checkpoint.h5" ] || fail "no checkpoint from --checkpoint-wall"
"$BIN" simulate "$WORK/job_wall.json" -o "$WORK/wall" --resume --checkpoint-wall 0.05 --progress quiet > /dev/null
resumed=$(h5dump -a /run/resumed_times "$WORK/wall/result.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
[ "$resumed" -ge 1 ] || fail "the wall-clock run did not resume from its checkpoint"
diff <(result_data "$WORK/wall_clean/result.h5") <(result_data "$WORK/wall/result.h5") > /dev/null \
  || fail "result after resuming from wall-clock checkpoints differs"
echo "ok  wall-clock checkpoints at arbitrary steps: bit-identical result"
