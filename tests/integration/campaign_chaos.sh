#!/usr/bin/env bash
# Chaos: SIGKILL the coordinator and workers at random moments of a small real campaign, re-run
# until it completes, and require every job to have exactly one result, bit-identical to a
# clean run's. Also: a second coordinator is refused while the first lives.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<'J'
{"name": "chaos",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 200, "target_rel_err": 1e-6, "min_window": 20, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.1, "inf"]}, {"w": [3, 4, 5]}]}}
J
results() {  # every result, to the last bit, in key order
  sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g|%!.17g', Q, Q_err, rho_n), exits_total, steps
                               FROM results ORDER BY job_key"
}
start=$(date +%s.%N)
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet
echo "clean campaign: $(echo "$(date +%s.%N) - $start" | bc) s"
clean=$(results "$WORK/clean")
[ "$(echo "$clean" | wc -l)" -eq 6 ] || fail "clean campaign did not finish 6 jobs"

# a second coordinator on a live campaign is refused
"$BIN" run "$WORK/sweep.json" --dir "$WORK/busy" --workers 1 --progress quiet &
first=$!
sleep 0.5
set +e; "$BIN" run "$WORK/sweep.json" --dir "$WORK/busy" --workers 1 --progress quiet 2> "$WORK/err"; rc=$?; set -e
kill -9 "$first" 2>/dev/null; wait "$first" 2>/dev/null || true
pkill -9 -f "worker $WORK/busy" 2>/dev/null || true
[ "$rc" -eq 6 ] || fail "second coordinator: exit $rc, expected 6 ($(cat "$WORK/err"))"
grep -q "another coordinator" "$WORK/err" || fail "second coordinator message: $(cat "$WORK/err")"
echo "ok  a second coordinator is refused: $(cat "$WORK/err")"

# chaos: kill at random moments, re-run until done
RANDOM=${CHAOS_SEED:-42}
rounds=0 coordinator_kills=0 worker_kills=0
while :; do
  rounds=$((rounds + 1))
  [ "$rounds" -le 40 ] || fail "no completion after 40 rounds"
  kill_round_begin
  "$BIN" run "$WORK/sweep.json" --dir "$WORK/chaos" --workers 2 --progress quiet 2>> "$WORK/chaos.log" &
  coord=$!
  sleep_backed_off $((RANDOM % 1000 + 200))  # ms
  if [ $((RANDOM % 3)) -ne 0 ]; then  # usually kill a worker first, then the coordinator
    pid=$(pgrep -f "worker $WORK/chaos" | head -n 1 || true)
    if [ -n "$pid" ]; then kill -9 "$pid" 2>/dev/null && worker_kills=$((worker_kills + 1)); fi
    sleep "0.$((RANDOM % 5))"
  fi
  if kill -9 "$coord" 2>/dev/null; then coordinator_kills=$((coordinator_kills + 1)); fi
  set +e; { wait "$coord"; } 2>/dev/null; rc=$?; set -e
  if [ "$rc" -eq 0 ]; then break; fi
  kill_round_end "$WORK/chaos"
  if [ $((RANDOM % 3)) -eq 0 ]; then pkill -9 -f "worker $WORK/chaos" 2>/dev/null || true; fi
done
# orphaned workers from killed coordinators may still run: the last coordinator adopted them
chaos=$(results "$WORK/chaos")
echo "chaos: $rounds rounds, $coordinator_kills coordinator kills, $worker_kills worker kills"
[ "$coordinator_kills" -ge 2 ] && [ "$worker_kills" -ge 1 ] || fail "too few kills to mean anything; lengthen the jobs"
dups=$(sqlite3 "$WORK/chaos/campaign.sqlite" "SELECT count(*) - count(DISTINCT job_key) FROM results")
[ "$dups" -eq 0 ] || fail "duplicate results"
[ "$(echo "$chaos" | wc -l)" -eq 6 ] || fail "chaos campaign has $(echo "$chaos" | wc -l) results, expected 6"
[ "$(sqlite3 "$WORK/chaos/campaign.sqlite" "SELECT count(*) FROM jobs WHERE state NOT IN ('done', 'clogged')")" -eq 0 ] \
  || fail "unfinished jobs after completion"
diff <(echo "$clean") <(echo "$chaos") > "$WORK/diff" || { cat "$WORK/diff"; fail "results differ from the clean campaign"; }
attempts=$(sqlite3 "$WORK/chaos/campaign.sqlite" "SELECT group_concat(failure_class || ':' || n) FROM (SELECT failure_class, count(*) n FROM attempts WHERE failure_class IS NOT NULL GROUP BY 1)")
echo "ok  every job exactly once, bit-identical to the clean campaign (failed attempts: ${attempts:-none})"
