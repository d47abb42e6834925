#!/usr/bin/env bash
# Adaptive campaigns in lambda (issue 30: "the same for lambda_c"): once every series of a
# beta(lambda) group is decided, the planner adds whole series (the grid's widths) at the lambda
# where the crossover fit needs them, until its budget of series is spent; the new series are
# refined like the others; a finished campaign run again decides nothing; the coordinator
# SIGKILLed at random moments gives the same decisions, jobs and bits; bad lambda blocks are
# refused naming their field.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<'J'
{"name": "adaptive-lambda",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 300, "target_rel_err": 1e-6, "min_window": 10, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.01, 0.1, 1]}, {"w": [3, 4, 5, 6]}]},
 "adaptive": {"target": {"k_err": 0.001}, "w_range": [2.5, 8], "w_step": 0.5, "max_added_jobs": 1,
              "lambda": {"target": {"log10_lambda_c_err": 0.001}, "range": [1e-3, 10], "per_decade": 4, "max_added_series": 2}}}
J
decisions() {
  sqlite3 "$1/campaign.sqlite" "SELECT series_key, seq, action, coalesce(job_key, '-'), coalesce(w, '-'), reason
                                FROM adaptive_decisions ORDER BY series_key, seq"
}
results() {
  sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g', Q, Q_err), steps FROM results ORDER BY job_key"
}
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet 2> "$WORK/clean.log"
clean=$(decisions "$WORK/clean")
group=$(echo "$clean" | grep '^lambda_' || true)
[ "$(echo "$group" | grep -c '|add|')" -eq 8 ] || fail "expected 2 new series of 4 widths in the group: $group"
[ "$(echo "$group" | grep -c '|stop|.*budget spent: 2 series')" -eq 1 ] || fail "the group should stop on its budget: $group"
lambdas=$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT count(DISTINCT printf('%.6g', lambda)) FROM jobs")
[ "$lambdas" -eq 5 ] || fail "expected 5 lambdas (3 of the grid, 2 added), got $lambdas"
# the new series are refined like the grid's: one added width each (max_added_jobs 1)
[ "$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT count(*) FROM jobs")" -eq 25 ] || fail "expected 12 + 3 + 8 + 2 jobs"
[ "$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT count(*) FROM jobs WHERE state <> 'done'")" -eq 0 ] || fail "jobs not done"
echo "$group" | cut -d'|' -f3,5,6 | sed 's/^/  /' | head -3
echo "ok  the group grew by 2 series where beta(lambda) is steep and stopped on its budget"

"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet 2> /dev/null
[ "$(decisions "$WORK/clean")" = "$clean" ] || fail "a finished campaign run again took new decisions"
echo "ok  a finished campaign run again decides nothing"

RANDOM=${CHAOS_SEED:-5}
dir="$WORK/chaos"
run_with_kills "$WORK/sweep.json" "$dir" 2500
[ "$(decisions "$dir")" = "$clean" ] || { diff <(echo "$clean") <(decisions "$dir"); fail "decisions differ after $kills kills"; }
[ "$(results "$dir")" = "$(results "$WORK/clean")" ] || fail "results differ after $kills kills"
[ "$kills" -ge 2 ] || fail "too few kills ($kills) to mean anything"
echo "ok  $kills coordinator kills in $rounds rounds: the same decisions, jobs and bits"

bad() {  # $1: the lambda block, $2: the field the message must name
  python3 - "$WORK/sweep.json" "$1" > "$WORK/bad.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); s["adaptive"]["lambda"] = json.loads(sys.argv[2]); print(json.dumps(s))
PY
  refused_without_writing "$WORK/bad.json" "$2" "lambda $1"
}
bad '{"range": [0.001, 10]}' 'adaptive.lambda.target'
bad '{"target": {"b_err": 0}, "range": [0.001, 10]}' 'adaptive.lambda.target.b_err'
bad '{"target": {"b_err": 0.1}, "range": [10, 0.001]}' 'adaptive.lambda.range'
bad '{"target": {"b_err": 0.1}, "range": [0.001, 10], "per_decade": 0}' 'adaptive.lambda.per_decade'
bad '{"target": {"b_err": 0.1}, "range": [0.001, 10], "max_added_series": 1.5}' 'adaptive.lambda.max_added_series'
bad '{"target": {"b_err": 0.1}, "range": [0.001, 10], "steps": 3}' 'adaptive.lambda.steps'
bad '{"target": {"crossing_interpolation_err": -0.1}, "range": [0.001, 10]}' 'adaptive.lambda.target.crossing_interpolation_err'
echo "ok  bad lambda blocks refused with their field named"

# The crossing target alone (no sigmoid): each new series goes at a candidate lambda
# 10^(k/per_decade) inside the pair that brackets where beta crosses d - 1, the one nearest the
# crossing, until the chord's interpolation error meets the target or no candidate is left.
cat > "$WORK/crossing.json" <<'J'
{"name": "adaptive-crossing",
 "base": {"N": 150, "W": 10, "E_sp": 100},
 "run": {"t_max": 300, "target_rel_err": 1e-6, "min_window": 10, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.001, 0.1, 10]}, {"w": [3, 4, 5, 6]}]},
 "adaptive": {"target": {"beta_err": 10}, "w_range": [2.5, 8],
              "lambda": {"target": {"crossing_interpolation_err": 0.001}, "range": [1e-3, 10], "per_decade": 4,
                         "max_added_series": 3}}}
J
"$BIN" sweep check "$WORK/crossing.json" | grep -q 'until crossing_interpolation_err <= 0.001$' \
  || fail "sweep check does not state the crossing target: $("$BIN" sweep check "$WORK/crossing.json")"
"$BIN" run "$WORK/crossing.json" --dir "$WORK/crossing" --workers 2 --progress quiet 2> "$WORK/crossing.log"
sqlite3 -separator $'\t' "$WORK/crossing/campaign.sqlite" \
  "SELECT action, coalesce(w, ''), reason FROM adaptive_decisions WHERE series_key LIKE 'lambda_%' ORDER BY seq" > "$WORK/crossing.rows"
python3 - "$WORK/crossing.rows" <<'PY' || fail "crossing decisions: $(cat "$WORK/crossing.rows")"
import math, re, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])]
adds = [r for r in rows if r[0] == "add"]
stops = [r for r in rows if r[0] == "stop"]
assert adds and len(adds) % 4 == 0, "whole series of the grid's 4 widths"
assert len(stops) == 1 and rows[-1][0] == "stop", "one stop, last"
for action, w, reason in adds:
    m = re.search(r"new series at lambda = ([0-9.e+-]+) .*crosses d - 1 at ([0-9.e+-]+) between ([0-9.e+-]+) and ([0-9.e+-]+)", reason)
    assert m, reason
    new, at, lo, hi = (float(x) for x in m.groups())
    assert lo < new < hi, f"{new} outside its bracket {lo} .. {hi}"
    k = math.log10(new) * 4
    assert abs(k - round(k)) < 1e-2, f"{new} is not a candidate 10^(k/4)"
stop = stops[0][2]
assert any(s in stop for s in ("crossing interpolation err", "the crossing as fine as per_decade 4", "budget spent")), stop
print("  " + adds[0][2][:110]); print("  " + stop[:140])
PY
echo "ok  the crossing target adds series inside the crossing's bracket and stops with its reason"
