#!/usr/bin/env bash
# A campaign database written before the Slurm executor (schema version 3, with jobs, attempts
# and results) is upgraded in place when a newer beverloo opens it for writing: attempts keep
# every row and column (the table is rebuilt for its new CHECK constraints), results still
# reference their attempts, and the new columns are there.
source "$(dirname "$0")/lib.sh"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
D=$WORK/old
mkdir -p "$D/jobs"
# the jobs carry this binary's engine version: retry puts back only a job this engine may run
# (integration/engine_upgrade.sh covers jobs of another engine)
V=$("$BIN" --version | grep -oE '[0-9]+\.[0-9]+\.[0-9]+' | head -1)
{
  cat "$ROOT"/schema/0001_*.sql "$ROOT"/schema/0002_*.sql "$ROOT"/schema/0003_*.sql
  sed "s/@ENGINE@/$V/g" <<'SQL'
PRAGMA application_id = 1112951887;
PRAGMA user_version = 3;
INSERT INTO campaigns (id, name, sweep_json, sweep_sha256) VALUES (1, 'old', '{}', 'x');
INSERT INTO jobs (key, dir, job_json, engine_version, model, dimension, N, size_ratio, W_container, w, theta_w_left_deg,
                  theta_w_right_deg, E_sp, E_w, zeta, mu, lambda, dissipation_scale, gravity, replica, seed, t_max,
                  target_rel_err, state)
  VALUES ('k1', 'jobs/k1', '{}', '@ENGINE@', 'sp', 2, 100, 1.4, 10, 4, 90, 90, 100, 1e4, 0.1, 1, 0.1, 0.316, 1, 0, 7, 100, 0.05, 'done'),
         ('k2', 'jobs/k2', '{}', '@ENGINE@', 'sp', 2, 100, 1.4, 10, 5, 90, 90, 100, 1e4, 0.1, 1, 0.1, 0.316, 1, 0, 8, 100, 0.05, 'failed');
INSERT INTO campaign_jobs VALUES (1, 'k1', 0, '{}'), (1, 'k2', 1, '{}');
INSERT INTO attempts (id, job_key, attempt_no, token, executor, host, pid, state, heartbeat_at, ended_at, exit_status,
                      failure_class, message)
  VALUES (1, 'k1', 1, 't1', 'local', 'vm', 11, 'succeeded', '2026-01-01T00:00:00Z', '2026-01-01T00:01:00Z', 0, NULL, NULL),
         (2, 'k2', 1, 't2', 'local', 'vm', 12, 'failed', NULL, '2026-01-01T00:02:00Z', 3, 'blow_up', 'overlap > 0.99');
INSERT INTO results (job_key, attempt_id, status, Q, Q_err, Q_rel_err, window_start, window_end, exits_in_window,
                     exits_total, clogged, dt, steps, wall_seconds, summary_json)
  VALUES ('k1', 1, 'converged', 4.5, 0.1, 0.022, 20, 100, 300, 400, 0, 1e-3, 100000, 12.5, '{}');
INSERT INTO beverloo_fit_results (series_key, label, dimension, N, E_sp, zeta, mu, lambda, theta_w_left_deg,
                                  theta_w_right_deg, points, clogged_points, C, k, beta)
  VALUES ('s1', '2D SP E_sp=100 lambda=0.1', 2, 100, 100, 0.1, 1, 0.1, 90, 90, 4, 0, 0.4, 1.5, 0.9);
INSERT INTO series_points VALUES ('s1', 4, 4.5, 0.1, 1, 0);
SQL
} | sqlite3 "$D/campaign.sqlite"
before=$(sqlite3 "$D/campaign.sqlite" "SELECT * FROM attempts ORDER BY id")
"$BIN" campaign retry --dir "$D" > "$WORK/out" || fail "opening the old database failed: $(cat "$WORK/out")"
[ "$(sqlite3 "$D/campaign.sqlite" "PRAGMA user_version")" -ge 4 ] || fail "not migrated"
after=$(sqlite3 "$D/campaign.sqlite" "SELECT id, job_key, attempt_no, token, executor, host, pid, state, started_at, heartbeat_at,
                                             ended_at, exit_status, failure_class, message FROM attempts ORDER BY id")
[ "$before" = "$after" ] || { diff <(echo "$before") <(echo "$after"); fail "attempts changed in the upgrade"; }
[ -z "$(sqlite3 "$D/campaign.sqlite" "PRAGMA foreign_key_check")" ] || fail "dangling references after the upgrade"
[ "$(sqlite3 "$D/campaign.sqlite" "SELECT r.Q FROM results r JOIN attempts a ON a.id = r.attempt_id")" = 4.5 ] || fail "results lost their attempt"
sqlite3 "$D/campaign.sqlite" "SELECT slurm_job_id, slurm_state, slurm_restarts FROM attempts; SELECT count(*) FROM slurm_submissions" > /dev/null \
  || fail "new columns missing"
[ "$(sqlite3 "$D/campaign.sqlite" "SELECT model, E_sp, K_b IS NULL, beta FROM beverloo_fits")" = "sp|100.0|1|0.9" ] \
  || fail "fits lost in the upgrade: $(sqlite3 "$D/campaign.sqlite" "SELECT * FROM beverloo_fits")"
grep -q "1 jobs back to pending" "$WORK/out" || fail "retry after the upgrade: $(cat "$WORK/out")"
echo "ok  schema 3 -> $(sqlite3 "$D/campaign.sqlite" "PRAGMA user_version"): attempts, results, fits and their references intact"
