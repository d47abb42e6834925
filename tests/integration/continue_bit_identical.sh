#!/usr/bin/env bash
# More flow time for a finished job: a job that differs from a finished one only in its
# stopping rules (run.min_time, run.target_rel_err, run.t_max, run.stop_unreachable) continues
# the finished job's final checkpoint (simulate --continue-from) and gives the result of a run
# from the start, bit for bit; a checkpoint this job's rules would have stopped before, or of
# another trajectory, is not continued (the run starts over, same result). A finished run's
# final checkpoint resumes to the same stop. With the argument "dp": the same for a smooth DP job.
source "$(dirname "$0")/lib.sh"
if [ "${1:-sp}" = dp ]; then
cat > "$WORK/a.json" <<'JOB'
{"model": "dp_smooth", "N": 60, "W": 8, "w": 3, "E_w": 100, "dp": {"E_c": 100}, "zeta": 0.3, "mu": 1.0,
 "run": {"t_max": 20, "target_rel_err": 0.3, "min_window": 2, "min_transient": 1, "rate_bin": 0.2,
         "check_interval": 0.5, "checkpoint_interval": 0.3}}
JOB
more=2
else
cat > "$WORK/a.json" <<'JOB'
{"N": 200, "W": 15, "w": 5, "zeta": 1, "mu": 0,
 "run": {"t_max": 400, "target_rel_err": 0.05, "min_window": 40, "checkpoint_interval": 30}}
JOB
more=60
fi
sim() { "$BIN" simulate "$@" --progress log 2> "$WORK/log" > /dev/null; }
t_end() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['t_end'])" "$1/summary.json"; }
status() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['status'])" "$1/summary.json"; }
same() { diff <(result_data "$1/result.h5") <(result_data "$2/result.h5") > "$WORK/diff" \
           || { head -30 "$WORK/diff"; fail "$3: the results differ"; }; }
with() {  # with OUT KEY VALUE ...: a.json with run.KEY = VALUE set
  python3 - "$WORK/a.json" "$WORK/$1.json" "${@:2}" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); a = sys.argv[3:]
for k, v in zip(a[::2], a[1::2]): j["run"][k] = json.loads(v)
json.dump(j, open(sys.argv[2], "w"))
PY
}

sim "$WORK/a.json" -o "$WORK/a"
[ -f "$WORK/a/checkpoint.h5" ] || fail "a finished run left no final checkpoint"
ta=$(t_end "$WORK/a")
echo "a: $(status "$WORK/a") at t = $ta"

# a time limit beyond any run is no limit (not a step count that overflows and stops the run at once)
with huge t_max 1e300
sim "$WORK/huge.json" -o "$WORK/huge"
[ "$(status "$WORK/huge")" = converged ] && [ "$(t_end "$WORK/huge")" = "$ta" ] \
  || fail "run.t_max 1e300: $(status "$WORK/huge") at t = $(t_end "$WORK/huge"), expected converged at $ta"
echo "ok  run.t_max 1e300 is no limit"

# a final checkpoint resumes to the same stop: the result removed, --resume writes it again
mkdir "$WORK/a_again" && cp "$WORK/a/checkpoint.h5" "$WORK/a/job.json" "$WORK/a_again/"
sim "$WORK/a.json" -o "$WORK/a_again" --resume
grep -q "resumed from checkpoint.h5" "$WORK/log" || fail "the final checkpoint was not resumed: $(cat "$WORK/log")"
same "$WORK/a" "$WORK/a_again" "a final checkpoint resumed"
echo "ok  a final checkpoint resumes to the same stop"

# more flow time: run.min_time beyond a's end, continued == from the start
with b min_time "$(python3 -c "print($ta + $more)")"
sim "$WORK/b.json" -o "$WORK/b_fresh"
sim "$WORK/b.json" -o "$WORK/b_cont" --continue-from "$WORK/a/checkpoint.h5"
grep -q "continued the run of" "$WORK/log" || fail "b did not continue a: $(cat "$WORK/log")"
same "$WORK/b_fresh" "$WORK/b_cont" "b continued from a"
python3 -c "import sys; sys.exit(0 if $(t_end "$WORK/b_cont") > $ta else 1)" || fail "b did not run longer than a"
# its engine time is its own, and its one resume the continuation
python3 -c "import json, sys; sys.exit(0 if json.load(open(sys.argv[1]))['resumed_times'] == 1 else 1)" "$WORK/b_cont/summary.json" \
  || fail "a continued run should count one resume"

echo "ok  run.min_time: continued from a's final checkpoint (t = $ta -> $(t_end "$WORK/b_cont")), bit-identical"

# a tighter error target with a later time limit: the same
with c target_rel_err 0.5e-9 t_max "$(python3 -c "print($ta + $more / 2)")"
sim "$WORK/c.json" -o "$WORK/c_fresh"
sim "$WORK/c.json" -o "$WORK/c_cont" --continue-from "$WORK/a/checkpoint.h5"
grep -q "continued the run of" "$WORK/log" || fail "c did not continue a: $(cat "$WORK/log")"
same "$WORK/c_fresh" "$WORK/c_cont" "c continued from a"
[ "$(status "$WORK/c_cont")" = time_limit ] || fail "c should end at its time limit"
echo "ok  run.target_rel_err and run.t_max: continued, bit-identical"

# a continued run killed and resumed from its own checkpoint: still the same
# (the binary itself in the background, not a function: kill -9 must reach the engine)
"$BIN" simulate "$WORK/b.json" -o "$WORK/b_kill" --continue-from "$WORK/a/checkpoint.h5" --checkpoint-wall 0.05 \
  --progress log 2> "$WORK/kill.log" > /dev/null &
pid=$!
for _ in $(seq 400); do grep -q "continued the run" "$WORK/kill.log" 2>/dev/null && break; sleep 0.01; done
sleep 0.3
kill -9 "$pid" 2>/dev/null || true
{ wait "$pid"; } 2>/dev/null || true
[ -f "$WORK/b_kill/result.h5" ] && rm "$WORK/b_kill/result.h5" "$WORK/b_kill/summary.json"
sim "$WORK/b.json" -o "$WORK/b_kill" --resume --continue-from "$WORK/a/checkpoint.h5"
same "$WORK/b_fresh" "$WORK/b_kill" "b killed and resumed"
echo "ok  a continued run killed and resumed: bit-identical"

# a checkpoint this job would have stopped before is not continued: a from b's end runs from the start
sim "$WORK/a.json" -o "$WORK/a_from_b" --continue-from "$WORK/b_cont/checkpoint.h5"
grep -q "not continuing .*before the checkpoint" "$WORK/log" || fail "a continued a later checkpoint: $(cat "$WORK/log")"
same "$WORK/a" "$WORK/a_from_b" "a not continued from b"
# another trajectory (another w) is not continued either
sed 's/"w": [0-9]*,/"w": 4,/' "$WORK/a.json" > "$WORK/d.json"
sim "$WORK/d.json" -o "$WORK/d" --continue-from "$WORK/a/checkpoint.h5"
grep -q "not continuing .*another trajectory" "$WORK/log" || fail "another trajectory was continued: $(cat "$WORK/log")"
echo "ok  a checkpoint past this job's stop, or of another trajectory: started over, the same result"
