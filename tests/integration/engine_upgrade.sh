#!/usr/bin/env bash
# A campaign begun by another engine version: its pending jobs are not run by this binary (their
# results would be stored as that engine's), they are cancelled with a message, `campaign retry`
# does not put them back, and `campaign status` lists the jobs by engine version. Its finished
# jobs keep their results.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<'SWEEP'
{"name": "upgrade", "base": {"dimension": 2, "N": 100, "W": 12, "E_sp": 100, "zeta": 0.3, "mu": 0},
 "run": {"t_max": 4, "min_window": 2, "min_transient": 1, "rate_bin": 0.2},
 "sweep": {"w": [4, 5, 6]}}
SWEEP
"$BIN" campaign create "$WORK/sweep.json" --dir "$WORK/c" > /dev/null
# as if an older engine had expanded the sweep and finished one job: w = 4 done, the rest pending
db="$WORK/c/campaign.sqlite"
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 1 --progress quiet > /dev/null 2>&1
key4=$(sqlite3 "$db" "SELECT job_key FROM campaign_jobs cj JOIN jobs j ON j.key = cj.job_key WHERE j.w = 4")
sqlite3 "$db" "UPDATE jobs SET engine_version = '0.0.1'; UPDATE jobs SET state = 'pending' WHERE w != 4; DELETE FROM results WHERE job_key IN (SELECT key FROM jobs WHERE w != 4);"
q4=$(sqlite3 "$db" "SELECT printf('%.17g', Q) FROM results WHERE job_key = '$key4'")
out=$("$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 1 --progress quiet 2>&1) || fail "run exited $?: $out"
echo "$out" | grep -q "2 pending job(s) of another engine version cancelled" || fail "no word about the older jobs: $out"
[ "$(sqlite3 "$db" "SELECT count(*) FROM results")" = 1 ] || fail "the older engine's pending jobs were run by this one"
[ "$(sqlite3 "$db" "SELECT count(*) FROM jobs WHERE state = 'cancelled' AND engine_version = '0.0.1'")" = 2 ] \
  || fail "the older engine's pending jobs are not cancelled"
[ "$(sqlite3 "$db" "SELECT printf('%.17g', Q) FROM results WHERE job_key = '$key4'")" = "$q4" ] || fail "a finished job lost its result"
echo "ok  pending jobs of another engine: cancelled, not run; its finished job keeps its result"
"$BIN" campaign retry --dir "$WORK/c" --include-cancelled > /dev/null 2>&1 || true
[ "$(sqlite3 "$db" "SELECT count(*) FROM jobs WHERE state = 'pending'")" = 0 ] || fail "retry put another engine's jobs back"
status=$("$BIN" campaign status --dir "$WORK/c")
echo "$status" | grep -q "^engines .*0.0.1: 3 jobs (1 with a result, 2 cancelled)" || fail "status does not list the versions: $status"
echo "ok  retry leaves them; campaign status lists the jobs by engine version"
