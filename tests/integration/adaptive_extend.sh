#!/usr/bin/env bash
# Adaptive campaigns with "extend" (issue 30: more flow time for an existing point): where a
# new run's start (its transient) costs more than a finished run's window, the planner gives a
# finished run its window again, as the job that differs only in run.min_time; that job
# continues the finished job's final checkpoint and its result is, bit for bit, that of the
# job run from the start; the fit takes the longer run as the point (not both); the same
# campaign killed at random moments takes the same decisions with the same results.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<J
{"name": "adaptive-extend",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 60, "target_rel_err": 1e-6, "min_window": 10, "min_transient": 40, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": ["inf"]}, {"w": [3, 4, 5, 6]}]},
 "adaptive": {"target": {"k_err": 0.001}, "w_range": [2.5, 8], "w_step": 0.5, "max_added_jobs": 3, "extend": true}}
J
decisions() {
  sqlite3 "$1/campaign.sqlite" "SELECT series_key, seq, action, coalesce(job_key, '-'), reason FROM adaptive_decisions ORDER BY series_key, seq"
}
results() {
  sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g', Q, Q_err), steps FROM results ORDER BY job_key"
}
start_ns=$(date +%s%N)
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress log 2> "$WORK/clean.log"
clean_ms=$(( ($(date +%s%N) - start_ns) / 1000000 ))
clean=$(decisions "$WORK/clean")
echo "$clean" | cut -c1-12,65- | sed 's/^/  /'
extended=$(echo "$clean" | grep '|add|.*more flow time' | cut -d'|' -f4)
[ -n "$extended" ] || fail "no run was given more flow time: $clean"
for key in $extended; do
  dir="$WORK/clean/$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT dir FROM jobs WHERE key = '$key'")"
  grep -q '"continue_from"' "$dir/spec.json" || fail "job $key: its spec names no checkpoint to continue"
  grep -q "continued the run of" "$dir/log" || fail "job $key did not continue: $(cat "$dir/log")"
  sqlite3 "$WORK/clean/campaign.sqlite" "SELECT job_json FROM jobs WHERE key = '$key'" > "$WORK/job.json"
  grep -q '"min_time"' "$WORK/job.json" || fail "job $key has no run.min_time"
  "$BIN" simulate "$WORK/job.json" -o "$WORK/fresh_$key" --progress quiet > /dev/null
  diff <(result_data "$WORK/fresh_$key/result.h5") <(result_data "$dir/result.h5") > /dev/null \
    || fail "job $key continued differs from the same job run from the start"
done
echo "ok  $(echo "$extended" | wc -w) run(s) given more flow time, each continued and bit-identical to a run from the start"

# the fit: the longer run is the point, the shorter one left out and said so
"$BIN" fit "$WORK/clean" > "$WORK/fit" 2>&1 || { cat "$WORK/fit"; fail "fit failed"; }
grep -q "continued by a longer run" "$WORK/fit" || { cat "$WORK/fit"; fail "fit does not say which runs were continued"; }
echo "ok  the fit takes the longer run of a trajectory, and says so"

# campaign explain: a job that differs from a stored one only in when it stops will continue it
python3 - "$WORK/job.json" "$WORK/longer.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j["run"]["min_time"] += 100; json.dump(j, open(sys.argv[2], "w"))
PY
"$BIN" campaign explain "$WORK/longer.json" --dir "$WORK/clean" > "$WORK/explain"
grep -q "^continues    only its stopping rules differ" "$WORK/explain" || { cat "$WORK/explain"; fail "explain does not say the job continues"; }
sed 's/"w": [0-9.]*/"w": 7.25/' "$WORK/longer.json" > "$WORK/other.json"
"$BIN" campaign explain "$WORK/other.json" --dir "$WORK/clean" > "$WORK/explain"
grep -q "^continues" "$WORK/explain" && fail "explain says another trajectory continues"
echo "ok  campaign explain says when a job will continue a stored one"

# killed at random moments: the same decisions, the same results
# (the delays stay well inside the clean run's time, so that a fast machine cannot finish the
# campaign before the first kill)
RANDOM=7
run_with_kills "$WORK/sweep.json" "$WORK/chaos" "$(( clean_ms / 2 > 50 ? clean_ms / 2 : 50 ))" 100
[ "$kills" -ge 1 ] || fail "the chaos run was never killed"
[ "$(decisions "$WORK/chaos")" = "$clean" ] || { diff <(echo "$clean") <(decisions "$WORK/chaos"); fail "the killed campaign decided otherwise"; }
[ "$(results "$WORK/chaos")" = "$(results "$WORK/clean")" ] || fail "the killed campaign's results differ"
echo "ok  killed $kills times: the same decisions and results"

# a bad extend is refused, naming its field
sed 's/"extend": true/"extend": "yes"/' "$WORK/sweep.json" > "$WORK/bad.json"
refused_without_writing "$WORK/bad.json" "adaptive.extend" "a non-boolean extend"
echo "ok  a bad adaptive.extend is refused"
