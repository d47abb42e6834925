#!/usr/bin/env bash
# Adaptive campaigns (issue 30): a small SP series grows by the planner's decisions until its
# budget is spent; the same sweep run again from scratch with the coordinator and workers
# killed (SIGKILL) at random moments takes the same decisions and adds the same jobs, each job
# once, with bit-identical results; a finished campaign run again adds nothing; the decisions
# are in the database and in `campaign status`; a bad adaptive block is refused, naming its field.
# The long form (issue 31 item 9, by hand: ctest -L validation -R adaptive_chaos): two series,
# 8 added jobs each, and at least CHAOS_MIN_KILLS (100) coordinator kills at short intervals.
source "$(dirname "$0")/lib.sh"
MIN_KILLS=${CHAOS_MIN_KILLS:-2}
ADDED=${ADAPTIVE_ADDED:-3}
LAMBDAS=${ADAPTIVE_LAMBDAS:-'"inf"'}
DELAY_MS=${CHAOS_DELAY_MS:-1500}
T_MAX=${ADAPTIVE_T_MAX:-300}
cat > "$WORK/sweep.json" <<J
{"name": "adaptive",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": $T_MAX, "target_rel_err": 1e-6, "min_window": 10, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [$LAMBDAS]}, {"w": [3, 4, 5, 6]}]},
 "adaptive": {"target": {"k_err": 0.001}, "w_range": [2.5, 8], "w_step": 0.5, "max_added_jobs": $ADDED}}
J
SERIES=$(echo "$LAMBDAS" | tr ',' '\n' | wc -l)
decisions() {
  sqlite3 "$1/campaign.sqlite" "SELECT series_key, seq, action, coalesce(job_key, '-'), coalesce(w, '-'), coalesce(replica, '-'),
                                reason FROM adaptive_decisions ORDER BY series_key, seq"
}
results() {
  sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g', Q, Q_err), steps FROM results ORDER BY job_key"
}
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet 2> "$WORK/clean.log"
clean=$(decisions "$WORK/clean")
echo "$clean" | cut -c1-12,65- | sed 's/^/  /'
[ "$(echo "$clean" | grep -c '|add|')" -eq $((SERIES * ADDED)) ] || fail "expected $ADDED added jobs per series (the budget), got: $clean"
[ "$(echo "$clean" | grep -c '|stop|.*budget spent')" -eq "$SERIES" ] || fail "every series should stop on its budget: $clean"
[ "$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT count(*) FROM results")" -eq $((SERIES * (4 + ADDED))) ] || fail "expected $((SERIES * (4 + ADDED))) results"
grep -q "adaptive .* add" "$WORK/clean.log" || fail "the coordinator did not log its decisions"
[ "$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT count(*) FROM runs WHERE engine_version IS NOT NULL")" -eq $((SERIES * (4 + ADDED))) ] \
  || fail "the runs view lacks the engine version"
echo "ok  $SERIES series grew by $ADDED jobs each and stopped on their budget"

# run again: nothing is added, nothing runs
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet 2> /dev/null
[ "$(decisions "$WORK/clean")" = "$clean" ] || fail "a finished campaign run again took new decisions"
echo "ok  a finished adaptive campaign run again decides nothing"

"$BIN" campaign status --dir "$WORK/clean" > "$WORK/status"
grep -q "adaptive" "$WORK/status" && grep -q "budget spent" "$WORK/status" || { cat "$WORK/status"; fail "campaign status does not show the decisions"; }
echo "ok  campaign status shows the decisions"
grep -q "Adaptive decisions" "$WORK/clean/report/index.html" && grep -q "budget spent" "$WORK/clean/report/index.html" \
  || fail "the report does not show the decisions"
echo "ok  the report shows the decisions"

# chaos: kill at random moments, re-run until done; the same decisions and results. Campaigns
# one after another (each in a fresh directory, each compared with the clean one) until at
# least MIN_KILLS coordinator kills in all: kills faster than a worker reaches its first
# checkpoint would only starve one campaign.
RANDOM=${CHAOS_SEED:-7}
total_kills=0 campaigns=0
while [ "$total_kills" -lt "$MIN_KILLS" ]; do
  campaigns=$((campaigns + 1))
  dir="$WORK/chaos$campaigns"
  run_with_kills "$WORK/sweep.json" "$dir" "$DELAY_MS"
  [ "$(decisions "$dir")" = "$clean" ] || { diff <(echo "$clean") <(decisions "$dir"); fail "campaign $campaigns: decisions differ after $kills kills"; }
  [ "$(results "$dir")" = "$(results "$WORK/clean")" ] || fail "campaign $campaigns: results differ after $kills kills"
  [ "$(sqlite3 "$dir/campaign.sqlite" "SELECT count(*) - count(DISTINCT job_key) FROM results")" -eq 0 ] || fail "duplicate results"
  echo "chaos campaign $campaigns: $rounds rounds, $kills coordinator kills: the same decisions, jobs and bits"
  total_kills=$((total_kills + kills))
  rm -rf "$dir"
done
echo "ok  $campaigns campaign(s), $total_kills coordinator kills in all: the same decisions, jobs and bits as the clean campaign"

# bad adaptive blocks: exit 2, the field named, nothing created
bad() {  # $1: adaptive block, $2: the field the message must name
  sed "s#\"adaptive\": .*}}\$#\"adaptive\": $1}#" "$WORK/sweep.json" > "$WORK/bad.json"
  refused_without_writing "$WORK/bad.json" "$2" "adaptive $1"
}
bad '{"w_range": [2, 8]}' 'adaptive.target'
bad '{"target": {"k_err": -1}, "w_range": [2, 8]}' 'adaptive.target.k_err'
bad '{"target": {"k_err": 0.1}, "w_range": [8, 2]}' 'adaptive.w_range'
bad '{"target": {"k_err": 0.1}, "w_range": [2, 8], "w_step": 1e-9}' 'adaptive.w_step'
bad '{"target": {"k_err": 0.1}, "w_range": [2, 8], "max_added_jobs": 2.5}' 'adaptive.max_added_jobs'
bad '{"target": {"k_er": 0.1}, "w_range": [2, 8]}' 'adaptive.target.k_er'
bad '"yes"' 'adaptive'
echo "ok  bad adaptive blocks refused with their field named"
