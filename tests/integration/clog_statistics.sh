#!/usr/bin/env bash
# Clogging as a result: replicas near k, some clogging, give per w the Kaplan-Meier probability
# to clog within t_max in `fit`'s output, the clog_statistics view and the report's figure; and
# `campaign explain` finds a finished job by its file and names what differs for a new one.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/s.json" <<'J'
{"name": "clogs", "base": {"dimension": 2, "N": 200, "W": 14, "E_sp": 1000, "zeta": 0, "mu": 10, "seed": 11},
 "run": {"t_max": 60, "t_clog": 6, "target_rel_err": 0.1}, "replicas": 4,
 "sweep": {"w": [2.2, 6]}}
J
"$BIN" run "$WORK/s.json" --dir "$WORK/c" --workers 2 --progress quiet > "$WORK/run.out" 2>&1 || { cat "$WORK/run.out"; fail "run"; }
"$BIN" fit "$WORK/c" > "$WORK/fit.out" || fail "fit"
grep -q "^Clogging: the time to a clog" "$WORK/fit.out" || { cat "$WORK/fit.out"; fail "fit printed no clog table"; }
clogs=$("$BIN" query "$WORK/c" "SELECT clogs FROM clog_statistics WHERE w = 2.2" --format csv | tail -1)
runs=$("$BIN" query "$WORK/c" "SELECT count(*) FROM runs WHERE w = 2.2 AND clogged = 1" --format csv | tail -1)
[ "$clogs" -ge 1 ] || fail "no clog at w = 2.2 (the test needs one): $clogs"
[ "$clogs" = "$runs" ] || fail "clog_statistics counts $clogs clogs where the runs view has $runs"
p=$("$BIN" query "$WORK/c" "SELECT p_clog FROM clog_statistics WHERE w = 2.2" --format csv | tail -1)
python3 -c "import sys; p = float('$p'); sys.exit(0 if ($clogs == 4 and p == 1.0) or (0 < p < 1) else 1)" \
  || fail "p_clog $p does not fit $clogs clogs of 4"
p6=$("$BIN" query "$WORK/c" "SELECT p_clog FROM clog_statistics WHERE w = 6" --format csv | tail -1)
clogs6=$("$BIN" query "$WORK/c" "SELECT count(*) FROM runs WHERE w = 6 AND clogged = 1" --format csv | tail -1)
[ "$clogs6" != 0 ] || [ "$p6" = 0 ] || [ "$p6" = 0.0 ] || fail "w = 6 had no clog but p_clog = $p6"
# the authors' way beside ours: printed only when asked, stored always
"$BIN" fit "$WORK/c" | grep -q "^Both ways" && fail "fit printed the authors' way without --authors-way"
"$BIN" fit "$WORK/c" --authors-way > "$WORK/fit2.out" || fail "fit --authors-way"
grep -q "^Both ways" "$WORK/fit2.out" || fail "fit --authors-way printed no side-by-side table"
rows=$("$BIN" query "$WORK/c" "SELECT count(*) FROM beverloo_fits_both_ways WHERE authors_points IS NOT NULL OR authors_message IS NOT NULL" --format csv | tail -1)
[ "$rows" -ge 1 ] || fail "beverloo_fits_both_ways holds no authors' fit or reason"
"$BIN" report "$WORK/c" > /dev/null 2>&1 || fail "report"
grep -q "Every exponent two ways" "$WORK/c/report/index.html" || fail "index.html lacks the two-ways table"
grep -q "<h2>Clogging" "$WORK/c/report/index.html" || fail "index.html lacks the clogging table"
if command -v gnuplot > /dev/null; then [ -s "$WORK/c/report/clog_survival.svg" ] || fail "no clog_survival figure"; fi
[ -s "$WORK/c/report/clog_survival.dat" ] || fail "no clog_survival data"

# campaign explain: a finished job by its file is cached; the same with another w is not, and differs in w
"$BIN" query "$WORK/c" "SELECT job_json FROM jobs WHERE w = 6 AND replica = 0" --format csv | tail -1 \
  | python3 -c "import csv, sys; print(next(csv.reader(sys.stdin))[0])" > "$WORK/job.json"
"$BIN" campaign explain "$WORK/job.json" --dir "$WORK/c" | grep -q "^cached       yes" || fail "explain: a done job not cached"
python3 - "$WORK/job.json" "$WORK/job2.json" <<'P'
import json, sys
j = json.load(open(sys.argv[1])); j["w"] = 5.5; json.dump(j, open(sys.argv[2], "w"))
P
"$BIN" campaign explain "$WORK/job2.json" --dir "$WORK/c" > "$WORK/explain.out"
grep -q "^cached       no" "$WORK/explain.out" || fail "explain: a new job cached"
grep -Eq "^  w +this 5.5 +stored 6" "$WORK/explain.out" || { cat "$WORK/explain.out"; fail "explain: w not named"; }
echo "clog statistics, both ways and explain ok"
