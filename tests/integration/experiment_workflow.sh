#!/usr/bin/env bash
# The experiment workflow end to end (docs/experiments.md): a small campaign of draining hoppers
# (45/45 and 45/0, drag only), its drains exported as a data file (labelled simulated), imported
# into the campaign, fitted beside the simulations, and shown in the report (Fig. 8c, 8d and
# N(t)). A bad file is refused with its line and column, and leaves the campaign as it was; a
# second import of a series is refused unless --replace.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<'JSON'
{"name": "drains", "base": {"dimension": 2, "N": 300, "W": 30, "E_sp": 100, "reinject": false, "lambda": "inf",
  "drain": {"fit_skip": 50}},
 "sweep": {"product": [{"union": [{"theta_w_deg": [45]}, {"theta_w_left_deg": [45], "theta_w_right_deg": [0]}]},
                       {"w": [3, 4, 5, 6]}]}}
JSON
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 2 --progress quiet > "$WORK/run.log" 2>&1 || { cat "$WORK/run.log"; fail "the drain campaign failed"; }
[ "$("$BIN" query "$WORK/c" "SELECT count(*) FROM runs WHERE status = 'drained' AND Q > 0" --format csv | tail -1)" = 8 ] \
  || fail "not every drain ended drained with a Q"
dirs=$("$BIN" query "$WORK/c" "SELECT dir FROM jobs WHERE theta_w_right_deg = 0 ORDER BY w" --format csv | tail -n +2 | sed "s|^|$WORK/c/|")
# shellcheck disable=SC2086
"$BIN" experiment export-drain $dirs -o "$WORK/sim.csv" --sigma-m 3.15e-4 --g-eff 0.639 --series "sim 45/0" --geometry 45/0 > /dev/null \
  || fail "export-drain failed"
grep -q "^# provenance: simulated" "$WORK/sim.csv" || fail "the exported file does not say it is simulated"
# a header value is one line: a line break in --series would forge a provenance line; an
# infinite unit would be written as inf and refused by the file's own import
# shellcheck disable=SC2086
refuse_export() {  # OPTION ARGS...: export-drain with ARGS exits 2 naming OPTION, and writes nothing
  local option=$1; shift
  # shellcheck disable=SC2086
  set +e; "$BIN" experiment export-drain $dirs -o "$WORK/forged.csv" "$@" > /dev/null 2> "$WORK/err"; local rc=$?; set -e
  [ "$rc" -eq 2 ] && grep -q -- "$option: " "$WORK/err" || fail "export-drain $* gave exit $rc: $(cat "$WORK/err")"
  [ ! -e "$WORK/forged.csv" ] || fail "a refused export-drain $* wrote a file"
}
refuse_export --series --series "$(printf 'x\n# provenance: measured')" --sigma-m 3.15e-4 --g-eff 0.639
refuse_export --geometry --geometry "$(printf '45/45\r')" --sigma-m 3.15e-4 --g-eff 0.639
refuse_export --g-eff --g-eff inf --sigma-m 3.15e-4
refuse_export --sigma-m --sigma-m 1e308 --g-eff 0.639

# a bad copy: a time that goes back on line 20; nothing may change in the campaign
sqlite3 "$WORK/c/campaign.sqlite" .dump > "$WORK/before.sql"
awk 'NR == 20 {$0 = "w3-x,0.000945,-1,5"} {print}' "$WORK/sim.csv" > "$WORK/bad.csv"
set +e; "$BIN" experiment import "$WORK/bad.csv" --dir "$WORK/c" > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] || fail "a bad file gave exit $rc, expected 2"
grep -q "bad.csv:20 column t_s" "$WORK/err" || fail "the message does not name line 20, column t_s: $(cat "$WORK/err")"
sqlite3 "$WORK/c/campaign.sqlite" .dump > "$WORK/after.sql"
cmp -s "$WORK/before.sql" "$WORK/after.sql" || fail "a refused import changed the campaign"
# and a refused import into a directory that is not a campaign creates nothing
set +e; "$BIN" experiment import "$WORK/bad.csv" --dir "$WORK/none" > /dev/null 2>&1; set -e
[ ! -e "$WORK/none" ] || fail "a refused import created $WORK/none"

"$BIN" experiment import "$WORK/sim.csv" --dir "$WORK/c" --fit-skip 50 > "$WORK/import.log" || fail "import failed: $(cat "$WORK/import.log")"
grep -q "stored 4 runs (4 fitted)" "$WORK/import.log" || fail "import did not fit 4 runs: $(cat "$WORK/import.log")"
set +e; "$BIN" experiment import "$WORK/sim.csv" --dir "$WORK/c" > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "already in this campaign" "$WORK/err" || fail "a second import of the series was not refused"
"$BIN" experiment import "$WORK/sim.csv" --dir "$WORK/c" --fit-skip 50 --replace > /dev/null || fail "--replace failed"
[ "$("$BIN" query "$WORK/c" "SELECT count(*) FROM experiment_results" --format csv | tail -1)" = 4 ] || fail "replace left other than 4 runs"
# the imported Q of each run equals the simulation's own Q (same exits, same fit, t0 units round trip)
"$BIN" query "$WORK/c" "SELECT e.w, e.Q, r.Q FROM experiment_results e JOIN runs r ON r.w = e.w AND r.theta_w_right_deg = 0" \
  --format csv | tail -n +2 | python3 -c '
import sys
for line in sys.stdin:
    w, qe, qr = map(float, line.split(","))
    assert abs(qe - qr) <= 1e-9 * qr, f"w = {w}: imported Q {qe} differs from the simulated {qr}"
' || fail "the imported Q differs from the simulation's"
# every drain ending round trips: a drain that stopped with particles left (drain.stop_below)
# keeps its N0; one job given twice, or two jobs at one width, stay two runs; a spreadsheet's
# byte-order mark is accepted; a newer format is refused, not misread
cat > "$WORK/left.json" <<'JSON'
{"dimension": 2, "N": 300, "W": 30, "w": 5, "E_sp": 100, "reinject": false, "zeta": 0.316227766, "mu": 0, "seed": 4,
 "drain": {"fit_skip": 30, "stop_below": 120}}
JSON
"$BIN" simulate "$WORK/left.json" -o "$WORK/left" --progress quiet > /dev/null || fail "the drain with particles left failed"
"$BIN" experiment export-drain "$WORK/left" "$WORK/left" -o "$WORK/left.csv" --sigma-m 3.15e-4 --g-eff 0.639 --series left \
  > /dev/null || fail "export-drain of one drain given twice failed"
printf '\xEF\xBB\xBF' | cat - "$WORK/left.csv" > "$WORK/left_bom.csv"
"$BIN" experiment import "$WORK/left_bom.csv" --dir "$WORK/c2" --fit-skip 30 > "$WORK/left.log" \
  || fail "a byte-order mark or a drain given twice was refused: $(cat "$WORK/left.log")"
grep -q "stored 2 runs (2 fitted)" "$WORK/left.log" || fail "one drain given twice is not two runs: $(cat "$WORK/left.log")"
python3 - "$WORK/left/summary.json" <<PY || fail "a drain with particles left does not give its own Q back"
import json, sqlite3, sys
q = json.load(open(sys.argv[1]))["Q"]
assert json.load(open(sys.argv[1]))["drain"]["n_remaining"] > 0, "the drain should have stopped with particles left"
con = sqlite3.connect("$WORK/c2/campaign.sqlite")
for (qi,) in con.execute("SELECT Q FROM experiment_results"):
    assert abs(qi - q) <= 1e-9 * q, (qi, q)
PY
sed 's/^# beverloo-exits 1$/# beverloo-exits 2/' "$WORK/left.csv" > "$WORK/newer.csv"
set +e; "$BIN" experiment import "$WORK/newer.csv" --dir "$WORK/c3" > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "beverloo-exits 2" "$WORK/err" || fail "a newer format was not refused: $rc $(cat "$WORK/err")"
[ ! -e "$WORK/c3" ] || fail "a refused newer format created a campaign"
"$BIN" fit "$WORK/c" > "$WORK/fit.log" || fail "fit failed"
grep -q "sim 45/0 (simulated by beverloo, not measured, 45/0)" "$WORK/fit.log" || fail "fit does not show the imported series as simulated"
"$BIN" report "$WORK/c" > /dev/null || fail "report failed"
for f in drain_Q_vs_w drain_collapse drain_curves; do
  [ -s "$WORK/c/report/$f.svg" ] || fail "the report has no $f figure"
done
grep -q "drain_curves.svg" "$WORK/c/report/index.html" || fail "index.html does not show N(t)"
echo "ok  drains -> export (simulated) -> import -> fit -> report; bad file refused at its line, campaign unchanged"
