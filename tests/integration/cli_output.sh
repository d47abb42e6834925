#!/usr/bin/env bash
# What the commands print, where docs/cli.md promises it: bench's JSON and its ratios to a
# baseline (and a bad baseline refused naming the file), the progress line (no Q and no window
# before the measurement window is open, never a window that ends before it starts), and
# `campaign status` explaining each state and run ending present.
source "$(dirname "$0")/lib.sh"

# bench --json, then --baseline of that file with the JSON on stdout and the lines on stderr
"$BIN" bench --case a --runs 1 --scale 0.01 --json "$WORK/base.json" > "$WORK/bench.txt" || fail "bench --json failed"
grep -q "^bench: 1 case(s) x 1 runs; roughly" "$WORK/bench.txt" || fail "bench does not say first how long it takes"
"$BIN" bench --case a --runs 1 --scale 0.01 --baseline "$WORK/base.json" --json - > "$WORK/new.json" 2> "$WORK/lines.txt" \
  || fail "bench --baseline failed"
grep -q "a: .* x the baseline's median" "$WORK/lines.txt" || fail "no ratio line: $(cat "$WORK/lines.txt")"
python3 - "$WORK/new.json" <<'PY' || fail "bench --json - is not the documented JSON"
import json, sys
j = json.load(open(sys.argv[1]))
c = j["cases"][0]
assert c["id"] == "a" and c["unit"] == "particle-steps/s" and c["median"] > 0, c
assert abs(c["ratio_to_baseline"] - c["median"] / c["baseline_median"]) < 1e-12, c
PY
echo '{"cases": [{"id": "a"}]}' > "$WORK/bad.json"
set +e; "$BIN" bench --case a --baseline "$WORK/bad.json" > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "bad.json: a case lacks its \"id\" or \"median\"" "$WORK/err" || fail "bad baseline: rc $rc, $(cat "$WORK/err")"
# what cannot be measured is refused (exit 2, naming the option or file), not printed as 0 or nan
for args in "--case z" "--case a --scale 1e-9" "--case a --baseline $WORK/zero.json"; do
  echo '{"cases": [{"id": "a", "median": 0}]}' > "$WORK/zero.json"
  # shellcheck disable=SC2086
  set +e; "$BIN" bench $args > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
  [ "$rc" -eq 2 ] || fail "bench $args gave exit $rc, expected 2: $(cat "$WORK/out" "$WORK/err")"
  grep -qE "^beverloo bench: (--case|--scale|$WORK/zero.json)" "$WORK/err" || fail "bench $args does not name what it refused: $(cat "$WORK/err")"
done
# a baseline without the case: said before the runs
echo '{"cases": [{"id": "b", "median": 5e7}]}' > "$WORK/other.json"
"$BIN" bench --case a --runs 1 --scale 0.01 --baseline "$WORK/other.json" > "$WORK/out" || fail "bench with another case set's baseline failed"
grep -q "^bench: the baseline .* has no case a: no ratio for it" "$WORK/out" || fail "a baseline without the case is not said: $(cat "$WORK/out")"
echo "ok  bench --json, --baseline, a bad baseline refused, unknown cases and empty scales refused"

# the progress line (terminal mode: a line every 0.25 s, split at its carriage returns):
# transient first, then Q with a window that starts before it ends
cat > "$WORK/job.json" <<'JOB'
{"dimension": 2, "N": 1600, "W": 40, "w": 5, "zeta": 0.3, "mu": 0, "seed": 2,
 "run": {"t_max": 60, "min_window": 15, "min_transient": 20, "target_rel_err": 1e-9, "check_interval": 5}}
JOB
"$BIN" simulate "$WORK/job.json" -o "$WORK/run" --progress terminal > /dev/null 2> "$WORK/raw"
tr '\r' '\n' < "$WORK/raw" | sed 's/\x1b\[K//' > "$WORK/progress"
grep -q "transient (no measurement window yet)" "$WORK/progress" || fail "no transient progress line: $(head -3 "$WORK/progress")"
python3 - "$WORK/progress" <<'PY' || fail "a progress line shows a window that ends before it starts"
import re, sys
seen = 0
for line in open(sys.argv[1]):
    m = re.search(r"window (\d+)-(\d+)", line)
    if m:
        seen += 1
        assert int(m.group(1)) < int(m.group(2)), line
        assert "transient" not in line, line
    elif "Q =" in line and line.startswith("t ="):
        raise AssertionError("Q without its window: " + line)
assert seen > 0, "no line with a window"
PY
echo "ok  progress lines: no Q before the window, windows in order"

# campaign status explains the states and endings it shows
cat > "$WORK/sweep.json" <<'JSON'
{"name": "s", "base": {"N": 100, "W": 12, "zeta": 0.3, "mu": 0},
 "run": {"t_max": 4, "min_window": 1, "min_transient": 1, "rate_bin": 0.1}, "sweep": {"w": [3, 4]}}
JSON
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 2 --progress quiet > /dev/null 2>&1 || fail "campaign failed"
"$BIN" campaign status --dir "$WORK/c" > "$WORK/status"
grep -q "^  done       finished; its result is stored" "$WORK/status" || fail "status does not explain 'done': $(cat "$WORK/status")"
grep -qE "^runs ended   2 (converged|time_limit): " "$WORK/status" || fail "status does not explain the endings: $(cat "$WORK/status")"
# and how fast its jobs ran, in t0 per CPU-minute: the same as each job's t_end over its wall time
line=$(grep -E "^speed        sp 2D: [0-9.e+]+ t0 per CPU-minute per job \(median of 2; " "$WORK/status") \
  || fail "status does not say how fast the jobs ran: $(cat "$WORK/status")"
"$BIN" query "$WORK/c" "SELECT json_extract(summary_json, '$.t_end') * 60.0 / wall_seconds FROM results ORDER BY 1" --format csv \
  | tail -n +2 | python3 -c '
import re, sys
v = [float(x) for x in sys.stdin.read().split()]
m = re.search(r"median of 2; ([0-9.e+]+)-([0-9.e+]+)\)", sys.argv[1])
lo, hi = float(m.group(1)), float(m.group(2))
assert abs(lo - v[0]) <= 6e-3 * v[0] and abs(hi - v[1]) <= 6e-3 * v[1], (lo, hi, v)  # 3 digits printed
' "$line" || fail "the speed line is not the jobs' own t_end / wall time: $line"
"$BIN" report "$WORK/c" > /dev/null || fail "report failed"
grep -q "t0 of flow per CPU-minute of a job" "$WORK/c/report/index.html" || fail "the report does not show the jobs' speed"
echo "ok  campaign status explains its states and endings, and the jobs' speed (also in the report)"

# a second sweep in the same directory: fit and report read the latest campaign by default,
# --campaign all every job of both once, --campaign ID one; a bad or missing ID is refused
# (exit 2, naming --campaign) with nothing written
sed 's/"w": \[3, 4\]/"w": [4, 5]/; s/"name": "s"/"name": "s2"/' "$WORK/sweep.json" > "$WORK/sweep2.json"
"$BIN" run "$WORK/sweep2.json" --dir "$WORK/c" --workers 2 --progress quiet > /dev/null 2>&1 || fail "second campaign failed"
points() { "$BIN" query "$WORK/c" "SELECT sum(points + clogged_points) FROM beverloo_fits" --format csv | tail -1; }
"$BIN" fit "$WORK/c" > /dev/null || fail "fit failed"
[ "$(points)" = 2 ] || fail "fit of the latest campaign stored $(points) points, expected 2 (w = 4, 5)"
"$BIN" fit "$WORK/c" --campaign all > "$WORK/out" || fail "fit --campaign all failed"
grep -q "^fit: every campaign (2) of " "$WORK/out" || fail "fit --campaign all does not say what it read: $(head -2 "$WORK/out")"
[ "$(points)" = 3 ] || fail "fit --campaign all stored $(points) points, expected 3 (w = 4 is in both campaigns, once)"
"$BIN" fit "$WORK/c" --campaign 1 > /dev/null && [ "$(points)" = 2 ] || fail "fit --campaign 1 stored $(points) points, expected 2"
for bad in 3 0 x; do
  rm -rf "$WORK/c/report"
  set +e; "$BIN" report "$WORK/c" --campaign "$bad" > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
  [ "$rc" -eq 2 ] && grep -q "^beverloo report: --campaign" "$WORK/err" || fail "report --campaign $bad gave exit $rc: $(cat "$WORK/err")"
  [ ! -e "$WORK/c/report" ] || fail "report --campaign $bad wrote the report"
done
"$BIN" report "$WORK/c" --campaign all > /dev/null || fail "report --campaign all failed"
grep -q "every campaign (2)" "$WORK/c/report/index.html" || fail "the report of all campaigns does not say so"
echo "ok  fit and report read the latest campaign, one by id, or all (each job once); a bad id refused"

# without gnuplot the report is still made: index.html, the tables, each figure's data and
# script, its images said to need gnuplot; exit 0 with a line on stderr
rm -rf "$WORK/c/report"
mkdir -p "$WORK/nopath"
env PATH="$WORK/nopath" "$BIN" report "$WORK/c" > "$WORK/out" 2> "$WORK/err" || fail "report without gnuplot failed: $(cat "$WORK/err")"
grep -q "gnuplot is not installed here" "$WORK/err" || fail "report without gnuplot does not say so: $(cat "$WORK/err")"
[ -s "$WORK/c/report/index.html" ] && [ -s "$WORK/c/report/Q_vs_w.gp" ] && [ -s "$WORK/c/report/beverloo_fits.csv" ] \
  || fail "report without gnuplot did not write index.html, the scripts and the tables"
grep -q "gnuplot is not installed here" "$WORK/c/report/index.html" || fail "index.html does not say why the figures are missing"
echo "ok  report without gnuplot: index.html, tables, data and scripts; the images said to need gnuplot"

# the process's own limits: a job beyond its address-space limit is refused before it runs
# (exit 2, the limit named); an allocation that fails anyway ends with exit 8, never an abort
echo '{"dimension": 2, "N": 50000000, "w": 6, "W": 3000, "zeta": 0.3, "mu": 0}' > "$WORK/big.json"
set +e; (ulimit -v 2097152; "$BIN" simulate "$WORK/big.json" -o "$WORK/big" > /dev/null 2> "$WORK/err"); rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "this process may use" "$WORK/err" || fail "a job beyond ulimit -v gave exit $rc: $(cat "$WORK/err")"
[ ! -e "$WORK/big" ] || fail "a refused job wrote $WORK/big"
set +e
(ulimit -v 400000; "$BIN" query "$WORK/c" "WITH RECURSIVE r(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM r LIMIT 20000000)
  SELECT x, printf('%0100d', x) FROM r" --max-rows 100000000 > /dev/null 2> "$WORK/err"); rc=$?
set -e
[ "$rc" -eq 8 ] && grep -q "out of memory" "$WORK/err" || fail "a query beyond ulimit -v gave exit $rc: $(cat "$WORK/err")"
echo "ok  the process's memory limit: a job refused before it runs, a query ends with exit 8"

