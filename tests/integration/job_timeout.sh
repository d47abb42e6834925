#!/usr/bin/env bash
# --job-timeout: an attempt that runs too long is asked to checkpoint and stop, is classed as
# "timeout" (no retry budget used), and later attempts resume it until it completes. The job
# must outlast the 0.8 s timeout by far on a fast engine: at 150 t0 engine 0.4.0 finished it first.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/sweep.json" <<'J'
{"name": "slow", "base": {"N": 300, "W": 12, "E_sp": 100, "zeta": 0.3, "mu": 0, "w": 4},
 "run": {"t_max": 600, "target_rel_err": 1e-6, "min_window": 20, "checkpoint_interval": 2}}
J
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 1 --job-timeout 0.8 --progress quiet
q() { sqlite3 "$WORK/c/campaign.sqlite" "$1"; }
timeouts=$(q "SELECT count(*) FROM attempts WHERE failure_class = 'timeout'")
[ "$timeouts" -ge 1 ] || fail "no attempt timed out"
[ "$(q "SELECT state FROM jobs")" = done ] || fail "the job did not complete"
[ "$(q "SELECT retries_used FROM jobs")" -eq 0 ] || fail "timeouts used up the retry budget"
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 1 --progress quiet
[ "$(q "SELECT printf('%!.17g', Q) FROM results")" = "$(sqlite3 "$WORK/clean/campaign.sqlite" "SELECT printf('%!.17g', Q) FROM results")" ] \
  || fail "the result after $timeouts timeouts differs from an uninterrupted run"
echo "ok  $timeouts timeouts, each resumed from its checkpoint; the result equals an uninterrupted run"
