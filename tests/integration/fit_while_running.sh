#!/usr/bin/env bash
# `beverloo fit` on a campaign whose coordinator is running fits the results stored so far
# read-only: it prints the fits, stores nothing and leaves the campaign's files as they were;
# after the coordinator has stopped, `fit` stores them as before; `--flow-rate Q_prime` fits
# Appendix B's Q' and stores nothing.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/s.json" <<'J'
{"name": "fit_busy", "base": {"N": 60, "W": 12, "zeta": 0.3, "mu": 0, "seed": 5},
 "run": {"t_max": 40, "target_rel_err": 0.2, "min_window": 8, "min_transient": 3}, "sweep": {"w": [3, 4, 5, 6]}}
J
"$BIN" run "$WORK/s.json" --dir "$WORK/c" --workers 2 --progress quiet > "$WORK/run.out" 2>&1 || { cat "$WORK/run.out"; fail "run"; }
command -v flock > /dev/null || fail "flock(1) is needed to hold the coordinator's lock"
# hold the coordinator's lock as a running coordinator does (flock on coordinator.lock)
flock -o "$WORK/c/coordinator.lock" sleep 60 &  # -o: the lock is flock's own, not sleep's
holder=$!
sleep 0.5
# (SQLite's WAL sidecars aside: a reader of a WAL database may create them, empty of content)
files() { cd "$WORK/c" && find . -type f ! -name coordinator.lock ! -name '*-wal' ! -name '*-shm' -exec sha256sum {} + | sort; }
before=$(files)
"$BIN" fit "$WORK/c" > "$WORK/fit.out" 2> "$WORK/fit.err" || { cat "$WORK/fit.err"; fail "fit on a busy campaign failed"; }
grep -q "fitted read-only" "$WORK/fit.out" || { cat "$WORK/fit.out"; fail "fit did not say it fitted read-only"; }
grep -q "^| series | points" "$WORK/fit.out" || { cat "$WORK/fit.out"; fail "fit printed no table"; }
grep -q "fits stored in" "$WORK/fit.out" && fail "a read-only fit claims to have stored its fits"
after=$(files)
[ "$before" = "$after" ] || fail "a read-only fit changed the campaign's files: $(diff <(echo "$before") <(echo "$after"))"
pkill -P "$holder" 2>/dev/null || true
kill "$holder" 2>/dev/null || true; wait "$holder" 2>/dev/null || true
echo "ok  fit on a busy campaign: printed, nothing written"
"$BIN" fit "$WORK/c" > "$WORK/fit2.out" || fail "fit after the coordinator stopped"
grep -q "fits stored in" "$WORK/fit2.out" || { cat "$WORK/fit2.out"; fail "fit did not store after the lock was free"; }
# the same table both ways
diff <(grep "^| 2D" "$WORK/fit.out") <(grep "^| 2D" "$WORK/fit2.out") || fail "the read-only fit differs from the stored one"
echo "ok  fit after the coordinator stopped: stored, the same table"
# Appendix B's Q': fitted and printed, never stored (the stored fits stay Q's)
before=$(files)
"$BIN" fit "$WORK/c" --flow-rate Q_prime > "$WORK/fitp.out" || fail "fit --flow-rate Q_prime"
grep -q "the flow rate Q' = Q a_eff / a_avg" "$WORK/fitp.out" || { cat "$WORK/fitp.out"; fail "no Q' header"; }
grep -q "^| 2D SP" "$WORK/fitp.out" || { cat "$WORK/fitp.out"; fail "no Q' table"; }
grep -q "fits stored in" "$WORK/fitp.out" && fail "a Q' fit claims to have stored its fits"
[ "$before" = "$(files)" ] || fail "a Q' fit changed the campaign's files"
# Q' differs from Q (the packing near the orifice is not the reference area), so its fit does too
[ "$(grep '^| 2D SP' "$WORK/fitp.out")" != "$(grep '^| 2D SP' "$WORK/fit2.out")" ] || fail "the Q' fit equals the Q fit"
set +e; "$BIN" fit "$WORK/c" --flow-rate rho_n > /dev/null 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -ne 0 ] || fail "an unknown --flow-rate was accepted"
echo "ok  fit --flow-rate Q_prime: printed, not stored, not Q's fit"
