#!/usr/bin/env bash
# Bad job files: exit 2, a message naming the file and the field, and nothing written.
source "$(dirname "$0")/lib.sh"
check() {  # name, expected text in the message, job json
  local name=$1 expect=$2 job=$3
  echo "$job" > "$WORK/$name.json"
  set +e
  "$BIN" simulate "$WORK/$name.json" -o "$WORK/out-$name" --progress quiet 2> "$WORK/err"
  local rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "$name: exit $rc, expected 2"
  grep -q -- "$expect" "$WORK/err" || fail "$name: message does not name '$expect': $(cat "$WORK/err")"
  # the file first, so that a user with several job files open sees which one is wrong
  grep -qF -- "$WORK/$name.json: " "$WORK/err" || fail "$name: message does not name the file: $(cat "$WORK/err")"
  [ ! -e "$WORK/out-$name" ] || fail "$name: wrote $WORK/out-$name"
  echo "ok  $name: $(cat "$WORK/err")"
}
check missing_w   "w: is required"          '{"zeta": 0.3, "mu": 0}'
check negative_w  "w: must be > 0"          '{"w": -2, "zeta": 0.3, "mu": 0}'
check typo        "run.tmax: unknown field" '{"w": 6, "zeta": 0.3, "mu": 0, "run": {"tmax": 10}}'
check dt_too_big  "dt: 0.002 is unstable for E_sp" '{"w": 6, "zeta": 0.3, "mu": 0, "E_sp": 1e5, "dt": 0.002}'
check bad_json    "is not valid JSON"       '{"w": 6, '
check angle       "theta_w_left_deg"        '{"w": 6, "zeta": 0.3, "mu": 0, "theta_w_deg": 120}'
check model       "model"                   '{"w": 6, "zeta": 0.3, "mu": 0, "model": "lj"}'
check overflow    "a number does not fit a double" '{"w": 1e400, "zeta": 0.3, "mu": 0}'
check explicit_N0 "N: must be in"       '{"w": 6, "zeta": 0.3, "mu": 0, "N": 0}'
check wrapped_int "N: must be in"       '{"w": 6, "zeta": 0.3, "mu": 0, "N": 4294967336}'
check deep        "nests deeper than 64"   "$(python3 -c "print('['*10000 + ']'*10000)")"
check duplicate   'the key "w" is given twice'        '{"w": 5, "w": 6, "zeta": 0.3, "mu": 0}'
check dup_nested  'the key "run.t_max" is given twice' '{"w": 6, "zeta": 0.3, "mu": 0, "run": {"t_max": 5, "t_max": 6}}'
check lanes_3d    "reinjection.rule"        '{"w": 4, "zeta": 0.3, "mu": 0, "dimension": 3, "reinjection": {"rule": "lanes"}}'
# a sweep whose product is 10^12 jobs is refused at once, not after reserving the memory
python3 -c "
import json
axes = [{'w': [3 + i * 0.001 for i in range(1000)]}, {'zeta': [0.1 + i * 0.001 for i in range(1000)]},
        {'mu': [0.1 + i * 0.001 for i in range(1000)]}, {'E_sp': [100 + i for i in range(1000)]}]
json.dump({'name': 'huge', 'base': {'N': 50, 'W': 12}, 'sweep': {'product': axes}}, open('$WORK/huge.json', 'w'))"
set +e; (ulimit -v 2000000; timeout 30 "$BIN" sweep check "$WORK/huge.json") 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "more than 1000000 points" "$WORK/err" || fail "a 10^12-job sweep: rc $rc, $(cat "$WORK/err")"
echo "ok  a 10^12-job sweep refused before expansion"
echo '{"name": "d", "base": {"N": 50, "W": 12, "zeta": 0.3, "mu": 0}, "sweep": {"union": [{"w": [3, 4]}, {"w": [4], "w": [5]}]}}' > "$WORK/dup.json"
set +e; "$BIN" sweep check "$WORK/dup.json" 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q 'sweep.union\[1\].w" is given twice' "$WORK/err" || fail "a duplicate key in a sweep: rc $rc, $(cat "$WORK/err")"
echo "ok  duplicate keys named with their place"
# limits before memory or time is spent: no hang on a FIFO, no read of a device
mkfifo "$WORK/fifo"
set +e; timeout 10 "$BIN" simulate "$WORK/fifo" -o "$WORK/x" 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "not a regular file" "$WORK/err" || fail "a FIFO as the job file: rc $rc, $(cat "$WORK/err")"
set +e; timeout 10 "$BIN" sweep check /dev/zero 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "not a regular file" "$WORK/err" || fail "/dev/zero as the sweep file: rc $rc, $(cat "$WORK/err")"
echo "ok  FIFO and device refused at once"
# an existing run is not silently overwritten
echo '{"w": 6, "zeta": 0.3, "mu": 0, "N": 100, "W": 12, "run": {"t_max": 2, "min_window": 1, "rate_bin": 0.1, "min_transient": 0}}' > "$WORK/ok.json"
"$BIN" simulate "$WORK/ok.json" -o "$WORK/ok" --progress quiet > /dev/null
set +e; "$BIN" simulate "$WORK/ok.json" -o "$WORK/ok" --progress quiet 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q -- "--resume" "$WORK/err" || fail "second run into the same directory must be refused (rc $rc)"
echo "all config error checks passed"
