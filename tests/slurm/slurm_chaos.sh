#!/usr/bin/env bash
# Chaos at the scale users run, through the real Slurm (issue 31.9; a validation test, run by
# hand: `ctest -L validation -R slurm_chaos`, ~10-20 min). A campaign of 12 jobs on the Slurm
# executor while, at random moments, the coordinator or a worker is SIGKILLed (CHAOS_KILLS in
# all, 100 by default), and once each: a running task requeued (scontrol requeue), the node set
# DOWN and resumed, slurmctld stopped and restarted with its saved state. Then the coordinator
# runs undisturbed to the end. Pass: every job done with exactly one succeeded attempt, no
# attempt left running, no temporary file left in a job directory, and every result
# bit-identical to the same campaign run locally without faults.
source "$(dirname "$0")/lib_slurm.sh"
KILLS=${CHAOS_KILLS:-100}
RANDOM=${CHAOS_SEED:-11}
ROOT=${SLURM_CI_ROOT:-/tmp/slurm-ci}
cat > "$WORK/sweep.json" <<'J'
{"name": "slurm-chaos",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 400, "target_rel_err": 1e-9, "min_window": 20, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.1, 1, "inf"]}, {"w": [3, 4, 5, 6]}]}}
J
"$BIN" run "$WORK/sweep.json" --dir "$WORK/local" --workers 2 --progress quiet > /dev/null 2>&1
clean=$(results "$WORK/local")
[ "$(echo "$clean" | wc -l)" -eq 12 ] || fail "local campaign did not finish 12 jobs"

D=$WORK/chaos
OPTS=(--executor slurm --bundle 1 --throttle 4 --poll-min 0.3 --poll-max 1 --heartbeat 1 --stall-timeout 20
      --result-grace 2 --progress log)
coordinator_kills=0 worker_kills=0 requeued=0 node_down=0 ctld_restarted=0 rounds=0
ctld_alive() { [ -f "$ROOT/run/slurmctld.pid" ] && kill -0 "$(cat "$ROOT/run/slurmctld.pid")" 2>/dev/null && scontrol ping > /dev/null 2>&1; }
running_task() {  # one RUNNING array task id of this campaign's arrays, or nothing
  squeue --noheader --array --states=RUNNING --format='%i %j' 2>/dev/null | awk '$2 ~ /^beverloo/ {print $1}' | head -1
}
coord=""
start_coordinator() {
  "$BIN" run "$WORK/sweep.json" --dir "$D" "${OPTS[@]}" > /dev/null 2>> "$WORK/chaos.log" &
  coord=$!
}
finished() {
  [ -f "$D/campaign.sqlite" ] && [ "$(q "$D" "SELECT count(*) FROM jobs WHERE state <> 'done'" 2>/dev/null || echo 1)" = 0 ]
}
start_coordinator
while [ $((coordinator_kills + worker_kills)) -lt "$KILLS" ]; do
  rounds=$((rounds + 1))
  [ "$rounds" -le $((KILLS * 6)) ] || fail "too many rounds without reaching $KILLS kills"
  delay=$((RANDOM % 1200 + 200))  # ms
  sleep "$((delay / 1000)).$(printf '%03d' $((delay % 1000)))"
  if ! kill -0 "$coord" 2>/dev/null; then  # it ended by itself (done, or an error)
    set +e; wait "$coord"; rc=$?; set -e
    [ "$rc" -eq 0 ] || [ "$rc" -eq 137 ] || { tail "$WORK/chaos.log"; fail "coordinator exit $rc"; }
    if finished; then
      # all done before the kills ran out: start over in a fresh directory, so that the faults
      # keep hitting a live campaign (each directory is checked at the end)
      mv "$D" "$D.$rounds"
    fi
    start_coordinator
    continue
  fi
  n=$((coordinator_kills + worker_kills))
  if [ "$requeued" = 0 ] && [ "$n" -ge $((KILLS / 4)) ] && task=$(running_task) && [ -n "$task" ]; then
    scontrol requeue "$task" 2>> "$WORK/chaos.log" && requeued=1 && echo "requeued $task after $n kills"
  elif [ "$node_down" = 0 ] && [ "$n" -ge $((KILLS / 2)) ]; then
    scontrol update nodename=localhost state=down reason=chaos
    sleep 2
    scontrol update nodename=localhost state=resume
    node_down=1 && echo "node set down and resumed after $n kills"
  elif [ "$ctld_restarted" = 0 ] && [ "$n" -ge $((3 * KILLS / 4)) ]; then
    kill -TERM "$(cat "$ROOT/run/slurmctld.pid")"
    wait_until 30 bash -c "! kill -0 $(cat "$ROOT/run/slurmctld.pid") 2>/dev/null" || fail "slurmctld did not stop"
    sleep 2  # the coordinator polls a controller that is not there
    /usr/sbin/slurmctld  # with its saved state (no -c)
    wait_until 60 ctld_alive || fail "slurmctld did not come back"
    ctld_restarted=1 && echo "slurmctld restarted after $n kills"
  elif [ $((RANDOM % 3)) -eq 0 ] && worker=$(pgrep -f -- "$BIN worker" | head -1) && [ -n "$worker" ]; then
    kill -9 "$worker" 2>/dev/null && worker_kills=$((worker_kills + 1))
  else
    if kill -9 "$coord" 2>/dev/null; then coordinator_kills=$((coordinator_kills + 1)); fi
    set +e; { wait "$coord"; } 2>/dev/null; set -e
    start_coordinator
  fi
done
echo "chaos: $rounds rounds, $coordinator_kills coordinator kills, $worker_kills worker kills"
[ "$requeued" = 1 ] || echo "note: no running task was found to requeue"
[ "$node_down" = 1 ] && [ "$ctld_restarted" = 1 ] || fail "the node and controller faults did not run"
# the last run, undisturbed (a node left drained would hang here: the test's timeout says so)
set +e; wait "$coord"; set -e
"$BIN" run "$WORK/sweep.json" --dir "$D" "${OPTS[@]}" > /dev/null 2>> "$WORK/chaos.log" || { tail "$WORK/chaos.log"; fail "the final run failed"; }
dirs=("$D")
for extra in "$D".*; do [ -d "$extra" ] && dirs+=("$extra"); done
for dir in "${dirs[@]}"; do
  [ "$(results "$dir")" = "$clean" ] || fail "$dir: results differ from the clean local campaign"
  [ "$(q "$dir" "SELECT count(*) FROM attempts WHERE state = 'succeeded'")" -eq 12 ] || fail "$dir: a job succeeded twice"
  [ "$(q "$dir" "SELECT count(*) FROM jobs WHERE state <> 'done'")" -eq 0 ] || fail "$dir: jobs not done"
  [ "$(q "$dir" "SELECT count(*) FROM attempts WHERE state = 'running'")" -eq 0 ] || fail "$dir: attempts left running"
  left=$(find "$dir/jobs" -name '*.tmp*' | head -3)
  [ -z "$left" ] || fail "$dir: temporary files left behind: $left"
  echo "    $(basename "$dir"): attempts $(q "$dir" "SELECT group_concat(n, ' ') FROM (SELECT state || ':' || count(*) AS n FROM attempts GROUP BY state)");" \
       "failure classes $(q "$dir" "SELECT group_concat(n, ' ') FROM (SELECT coalesce(failure_class, '-') || ':' || count(*) AS n FROM attempts GROUP BY failure_class)");" \
       "submissions $(q "$dir" "SELECT count(*) FROM slurm_submissions")"
done
echo "ok  ${#dirs[@]} campaign(s) through $coordinator_kills coordinator and $worker_kills worker SIGKILLs, a requeue, a node down and up, a slurmctld restart: every job exactly once, results bit-identical"
