#!/usr/bin/env bash
# A small campaign through the real Slurm gives the same results, bit for bit, as the local
# executor; then the same campaign with its coordinator SIGKILLed at random moments (and once
# exactly between sbatch and recording the array's id) completes with every job exactly once.
source "$(dirname "$0")/lib_slurm.sh"
cat > "$WORK/sweep.json" <<'J'
{"name": "slurm-same",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 300, "target_rel_err": 1e-6, "min_window": 20, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.1, "inf"]}, {"w": [3, 4, 5]}]}}
J
SLURM_OPTS=(--executor slurm --bundle 2 --throttle 2 --poll-min 0.5 --poll-max 1 --heartbeat 1 --progress log)

"$BIN" run "$WORK/sweep.json" --dir "$WORK/local" --workers 2 --progress quiet 2> /dev/null
clean=$(results "$WORK/local")
[ "$(echo "$clean" | wc -l)" -eq 6 ] || fail "local campaign did not finish 6 jobs"

start=$(date +%s.%N)
"$BIN" run "$WORK/sweep.json" --dir "$WORK/slurm" "${SLURM_OPTS[@]}" 2> "$WORK/slurm.log" || { cat "$WORK/slurm.log"; fail "slurm campaign failed"; }
echo "slurm campaign: $(echo "$(date +%s.%N) - $start" | bc) s"
grep "slurm:" "$WORK/slurm.log"
[ "$(results "$WORK/slurm")" = "$clean" ] || fail "slurm results differ from the local executor's"
[ "$(q "$WORK/slurm" "SELECT count(*) || ' ' || sum(array_size) || ' ' || max(throttle) FROM slurm_submissions WHERE state = 'submitted'")" = "1 3 2" ] \
  || fail "expected one array of 3 tasks (2 jobs each) throttled to 2: $(q "$WORK/slurm" "SELECT * FROM slurm_submissions")"
[ "$(q "$WORK/slurm" "SELECT count(*) FROM attempts WHERE executor = 'slurm' AND state = 'succeeded' AND slurm_job_id LIKE '%\_%' ESCAPE '\'")" -eq 6 ] \
  || fail "attempts lack their Slurm ids"
[ "$(q "$WORK/slurm" "SELECT count(*) FROM attempts WHERE heartbeat_at IS NOT NULL")" -eq 6 ] || fail "heartbeats not recorded"
echo "ok  same results as the local executor (6 jobs, one array of 3 tasks, throttle 2)"

# the window between sbatch and recording its id: the restarted coordinator finds the array by
# name and does not submit again
set +e; BEVERLOO_FAULT=after_sbatch "$BIN" run "$WORK/sweep.json" --dir "$WORK/fault" "${SLURM_OPTS[@]}" 2> "$WORK/fault.log"; rc=$?; set -e
[ "$rc" -eq 86 ] || { cat "$WORK/fault.log"; fail "fault injection: exit $rc"; }
[ "$(q "$WORK/fault" "SELECT state FROM slurm_submissions")" = submitting ] || fail "the submission should be left 'submitting'"
"$BIN" run "$WORK/sweep.json" --dir "$WORK/fault" "${SLURM_OPTS[@]}" 2> "$WORK/fault2.log" || { cat "$WORK/fault2.log"; fail "re-run after the fault failed"; }
[ "$(q "$WORK/fault" "SELECT count(*), group_concat(state) FROM slurm_submissions")" = "1|submitted" ] \
  || fail "re-run submitted again or lost the array: $(q "$WORK/fault" "SELECT * FROM slurm_submissions")"
[ "$(q "$WORK/fault" "SELECT count(*) FROM attempts")" -eq 6 ] || fail "jobs ran more than once after the fault"
[ "$(results "$WORK/fault")" = "$clean" ] || fail "results after the fault differ"
echo "ok  coordinator killed between sbatch and commit: array found by name, nothing submitted twice"

# chaos: SIGKILL the coordinator at random moments, re-run until done
RANDOM=${CHAOS_SEED:-7}
rounds=0 kills=0
while :; do
  rounds=$((rounds + 1))
  [ "$rounds" -le 40 ] || fail "no completion after 40 rounds"
  kill_round_begin
  "$BIN" run "$WORK/sweep.json" --dir "$WORK/chaos" --executor slurm --bundle 1 --poll-min 0.3 --poll-max 1 \
      --heartbeat 1 --progress log 2>> "$WORK/chaos.log" &
  coord=$!
  sleep_backed_off $((RANDOM % 1500 + 100))  # ms
  if kill -9 "$coord" 2>/dev/null; then kills=$((kills + 1)); fi
  set +e; { wait "$coord"; } 2>/dev/null; rc=$?; set -e
  [ "$rc" -eq 0 ] && break
  [ "$rc" -eq 137 ] || { tail "$WORK/chaos.log"; fail "coordinator exit $rc"; }
  kill_round_end "$WORK/chaos"
done
echo "chaos: $rounds rounds, $kills coordinator kills"
[ "$kills" -ge 2 ] || fail "too few kills to mean anything"
[ "$(results "$WORK/chaos")" = "$clean" ] || fail "chaos results differ from the clean run"
[ "$(q "$WORK/chaos" "SELECT count(*) FROM attempts WHERE state = 'succeeded'")" -eq 6 ] || fail "a job succeeded twice"
[ "$(q "$WORK/chaos" "SELECT count(*) FROM jobs WHERE state <> 'done'")" -eq 0 ] || fail "jobs not done"
[ "$(q "$WORK/chaos" "SELECT count(*) FROM attempts WHERE state = 'running'")" -eq 0 ] || fail "attempts left running"
echo "ok  coordinator SIGKILLed $kills times: every job exactly once, results identical"
echo "    attempts: $(q "$WORK/chaos" "SELECT group_concat(n, ' ') FROM (SELECT state || ':' || count(*) AS n FROM attempts GROUP BY state)")"
echo "    submissions: $(q "$WORK/chaos" "SELECT group_concat(n, ' ') FROM (SELECT state || ':' || count(*) AS n FROM slurm_submissions GROUP BY state)")"
