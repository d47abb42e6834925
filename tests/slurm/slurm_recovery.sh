#!/usr/bin/env bash
# Recovery through the real Slurm, three jobs of one campaign, one array task each:
#  - task 0 is cancelled with scancel: the job is marked cancelled (a user's decision is not
#    overruled), and `campaign retry --include-cancelled` + a re-run finish it from its checkpoint;
#  - task 1 is requeued with scontrol: the same attempt runs again (SLURM_RESTART_COUNT = 1)
#    and resumes from its checkpoint;
#  - task 2 gets USR1 as Slurm sends it before a time limit (--signal=B:USR1@lead; sent by hand
#    with scancel --signal=USR1 --batch, as slurm-notes.md advises): the worker checkpoints and
#    exits 5, and a new attempt resumes from the checkpoint;
#  - task 3's worker is frozen (SIGSTOP): its heartbeat goes stale, the coordinator cancels the
#    task and a new attempt resumes from the checkpoint (it waits for the frozen one's lock).
# Every job ends with exactly one result, bit-identical to the local executor's.
source "$(dirname "$0")/lib_slurm.sh"
cat > "$WORK/sweep.json" <<'J'
{"name": "slurm-recovery",
 "base": {"N": 150, "W": 10, "E_sp": 100, "w": 4},
 "run": {"t_max": 1500, "target_rel_err": 1e-9, "min_window": 20, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.1, 1, "inf", 10]}]}}
J
"$BIN" run "$WORK/sweep.json" --dir "$WORK/local" --workers 2 --progress quiet > /dev/null 2>&1
clean=$(results "$WORK/local")
[ "$(echo "$clean" | wc -l)" -eq 4 ] || fail "local campaign did not finish 4 jobs"
echo "local reference: $(q "$WORK/local" "SELECT group_concat(printf('%.1f s', wall_seconds), ', ') FROM results")"

D=$WORK/slurm
"$BIN" run "$WORK/sweep.json" --dir "$D" --executor slurm --bundle 1 --poll-min 0.5 --poll-max 1 --heartbeat 1 \
    --stall-timeout 5 --result-grace 2 --progress log > /dev/null 2> "$WORK/run1.log" &
coord=$!
submitted() { [ -n "$(q "$D" "SELECT slurm_job_id FROM slurm_submissions WHERE state = 'submitted'" 2>/dev/null)" ]; }
wait_until 60 submitted || fail "nothing submitted"
A=$(q "$D" "SELECT slurm_job_id FROM slurm_submissions")
all_running() { for t in 0 1 2 3; do [ "$(task_state "${A}_$t")" = RUNNING ] || return 1; done; }
wait_until 60 all_running || fail "tasks did not start: $(squeue --array -j "$A")"
dir_of() { echo "$D/$(q "$D" "SELECT j.dir FROM attempts a JOIN jobs j ON j.key = a.job_key WHERE a.slurm_job_id = '${A}_$1'")"; }
for t in 0 1 2 3; do wait_until 60 test -f "$(dir_of $t)/checkpoint.h5" || fail "task $t wrote no checkpoint"; done

scancel "${A}_0"
requeued_pid=$(grep -o '"pid":[0-9]*' "$(dir_of 1)/heartbeat.json" | grep -o '[0-9]*')
scontrol requeue "${A}_1"
requeued() { [ "$(task_state "${A}_1")" = PENDING ]; }
wait_until 20 requeued || fail "requeued task is $(task_state "${A}_1")"
# skip the 120 s BeginTime hold of a requeue, once the old run is gone: released earlier, Slurm
# 22.05 may kill the restart ("Job credential revoked") and the task ends FAILED (then the job
# is simply resubmitted, but that is not what this test is about)
gone() { ! kill -0 "$requeued_pid" 2> /dev/null; }
wait_until 30 gone || fail "the requeued task's worker did not stop"
sleep 2
scontrol update jobid="${A}_1" starttime=now
scancel --signal=USR1 --batch "${A}_2"
frozen=$(grep -o '"pid":[0-9]*' "$(dir_of 3)/heartbeat.json" | grep -o '[0-9]*')
kill -STOP "$frozen"

set +e; wait "$coord"; rc=$?; set -e
cat "$WORK/run1.log" | grep -v "jobs .* finished" || true
[ "$rc" -eq 0 ] || fail "first run: exit $rc"
key_of() { q "$D" "SELECT job_key FROM attempts WHERE slurm_job_id = '${A}_$1'"; }
k0=$(key_of 0) k1=$(key_of 1) k2=$(key_of 2) k3=$(key_of 3)
[ "$(q "$D" "SELECT state FROM jobs WHERE key = '$k0'")" = cancelled ] || fail "scancel'd job is not cancelled"
[ "$(q "$D" "SELECT failure_class FROM attempts WHERE job_key = '$k0'")" = cancelled ] || fail "scancel'd attempt class"
echo "ok  scancel: job cancelled, not retried behind the user's back"
[ "$(q "$D" "SELECT count(*) || ' ' || max(state) || ' ' || max(slurm_restarts) FROM attempts WHERE job_key = '$k1'")" = "1 succeeded 1" ] \
  || fail "requeued job: $(q "$D" "SELECT state, slurm_restarts, slurm_state, slurm_job_id, message FROM attempts WHERE job_key = '$k1'")"
grep -q "resumed from checkpoint" "$(dir_of 1)/log" || fail "requeued task did not resume from its checkpoint"
echo "ok  scontrol requeue: same attempt ran again (restart 1), resumed from its checkpoint, done"
[ "$(q "$D" "SELECT group_concat(state || ':' || coalesce(failure_class, ''), ' ') FROM attempts WHERE job_key = '$k2' ORDER BY attempt_no")" = "interrupted:interrupted succeeded:" ] \
  || fail "signalled job: $(q "$D" "SELECT attempt_no, state, failure_class, message FROM attempts WHERE job_key = '$k2'")"
echo "ok  USR1 before the time limit: checkpoint, exit 5, a second attempt resumed and finished"
[ "$(q "$D" "SELECT group_concat(state || ':' || coalesce(failure_class, ''), ' ') FROM attempts WHERE job_key = '$k3' ORDER BY attempt_no")" = "lost:stalled succeeded:" ] \
  || fail "frozen job: $(q "$D" "SELECT attempt_no, state, failure_class, message FROM attempts WHERE job_key = '$k3'")"
! kill -0 "$frozen" 2>/dev/null || fail "the frozen worker still lives"
echo "ok  stalled heartbeat: task cancelled, a new attempt resumed and finished"

"$BIN" campaign retry --dir "$D" --include-cancelled
"$BIN" campaign run --dir "$D" --executor slurm --poll-min 0.5 --poll-max 1 --heartbeat 1 --stall-timeout 5 --progress quiet 2> "$WORK/run2.log" \
  || { cat "$WORK/run2.log"; fail "re-run after retry failed"; }
[ "$(q "$D" "SELECT state FROM jobs WHERE key = '$k0'")" = done ] || fail "retried job not done"
[ "$(q "$D" "SELECT count(*) FROM attempts WHERE state = 'succeeded'")" -eq 4 ] || fail "not exactly one success per job"
for k in $k0 $k1 $k2 $k3; do
  resumed=$(h5dump -a /run/resumed_times "$D/$(q "$D" "SELECT dir FROM jobs WHERE key = '$k'")/result.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
  [ "$resumed" -ge 1 ] || fail "job $k did not resume from a checkpoint"
done
[ "$(results "$D")" = "$clean" ] || { diff <(echo "$clean") <(results "$D"); fail "results differ from the local executor's"; }
echo "ok  retry of the cancelled job resumed it; all 4 results bit-identical to the local executor's"
