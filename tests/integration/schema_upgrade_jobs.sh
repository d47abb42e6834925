#!/usr/bin/env bash
# Schema 0010 rebuilds `jobs` with only what is not a parameter stored (and the seed); every
# parameter column becomes a generated column over job_json. A campaign written at schema 9,
# whose jobs carry those columns as stored values, is upgraded in place when a newer beverloo
# opens it for writing: every row, its state and retries, every value a query reads from jobs
# or the runs view, the references to jobs and the indexes are what they were; E_sp of a DP
# job alone changes (NULL: the DP job does not carry it; it held the unused default).
source "$(dirname "$0")/lib.sh"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
q() { sqlite3 "$1/campaign.sqlite" "$2"; }

# 1. The jobs of a real sweep (SP and DP, two widths, a given seed and a derived one), made by
#    this binary: their canonical JSON and the values each column should hold.
cat > "$WORK/sweep.json" <<'JSON'
{"name": "upgrade", "base": {"N": 40, "W": 10, "zeta": 0.3, "mu": 0.0, "run": {"t_max": 30}},
 "sweep": {"product": [{"model": ["sp", "dp_smooth"]}, {"w": [4, 5.5]}, {"replica": [0, 1]}]}}
JSON
"$BIN" campaign create "$WORK/sweep.json" --dir "$WORK/new" > /dev/null
[ "$(q "$WORK/new" "PRAGMA user_version")" -ge 10 ] || fail "a new campaign is not at schema 10"
OLD_COLS="model, dimension, N, size_ratio, W_container, w, theta_w_left_deg, theta_w_right_deg, E_sp, E_w, zeta, mu,
          gravity, replica, t_max, target_rel_err, n_v, K_a, K_l, K_b, E_c"
# the rows as schema 9 stored them: E_sp held the default 100 for a DP job (NOT NULL since 0001)
# (reals to 17 digits: every bit; lambda = inf as 9e999, as the store writes it)
r() { echo "CASE WHEN $1 IS NULL THEN 'NULL' WHEN $1 > 1e308 THEN '9e999' ELSE printf('%.17g', $1) END"; }
rows=$(q "$WORK/new" "SELECT printf('(%Q, %Q, %Q, %Q, %s, %s, %d, %Q, %d, %Q, %d, %d, %s, %s, %s, %s, %s, %s, %s, %s, %s, %s, %d, %s, %s, %s, %s, %s, %s, %s),',
          key, dir, job_json, engine_version, $(r lambda), $(r dissipation_scale), seed, 'done', 1, model, dimension, N,
          $(r size_ratio), $(r W_container), $(r w), $(r theta_w_left_deg), $(r theta_w_right_deg), $(r 'coalesce(E_sp, 100)'),
          $(r E_w), $(r zeta), $(r mu), $(r gravity), replica, $(r t_max), $(r target_rel_err), coalesce(n_v, 'NULL'),
          $(r K_a), $(r K_l), $(r K_b), $(r E_c)) FROM jobs ORDER BY key" \
       | sed '$ s/,$/;/')
[ "$(q "$WORK/new" "SELECT count(*) FROM jobs")" -eq 8 ] || fail "expected 8 jobs"

# 2. A schema-9 campaign holding those jobs, one of them with a result and a velocity profile.
D=$WORK/old
mkdir -p "$D/jobs"
{
  for f in "$ROOT"/schema/000[1-9]_*.sql; do cat "$f"; echo; done
  echo "PRAGMA application_id = 1112951887; PRAGMA user_version = 9;"
  echo "INSERT INTO campaigns (id, name, sweep_json, sweep_sha256) VALUES (1, 'upgrade', '{}', 'x');"
  echo "INSERT INTO jobs (key, dir, job_json, engine_version, lambda, dissipation_scale, seed, state, retries_used, model,"
  echo "  dimension, N, size_ratio, W_container, w, theta_w_left_deg, theta_w_right_deg, E_sp, E_w, zeta, mu, gravity, replica,"
  echo "  t_max, target_rel_err, n_v, K_a, K_l, K_b, E_c) VALUES"
  echo "$rows"
  echo "INSERT INTO campaign_jobs SELECT 1, key, rowid, '{}' FROM jobs;"
  echo "INSERT INTO attempts (id, job_key, attempt_no, token, executor, state) SELECT 1, key, 1, 't1', 'local', 'succeeded' FROM jobs ORDER BY key LIMIT 1;"
  echo "INSERT INTO results (job_key, attempt_id, status, Q, Q_err, Q_rel_err, window_start, window_end, exits_in_window,"
  echo "  exits_total, clogged, dt, steps, wall_seconds, summary_json) SELECT job_key, 1, 'converged', 4.5, 0.1, 0.022, 20, 100,"
  echo "  300, 400, 0, 1e-3, 100000, 12.5, '{\"t_end\": 100}' FROM attempts;"
  echo "INSERT INTO velocity_profiles SELECT job_key, 0.5, 1.25, 0.1 FROM attempts;"
} | sqlite3 "$D/campaign.sqlite" || fail "could not build the schema-9 database"
before=$(q "$D" "SELECT key, dir, job_json, engine_version, lambda, dissipation_scale, seed, state, retries_used,
                        $OLD_COLS FROM jobs WHERE model = 'sp' ORDER BY key")
before_dp=$(q "$D" "SELECT key, $(echo "$OLD_COLS" | sed 's/E_sp, //') FROM jobs WHERE model <> 'sp' ORDER BY key")
before_runs=$(q "$D" "SELECT key, state, model, w, E_sp IS NOT NULL, seed, Q FROM runs ORDER BY key")
[ "$(echo "$before" | wc -l)" -eq 4 ] && [ "$(echo "$before_dp" | wc -l)" -eq 4 ] || fail "the schema-9 jobs were not made"

# 3. Open it for writing (retry migrates; nothing is failed, so it changes no state).
"$BIN" campaign retry --dir "$D" > "$WORK/out" 2>&1 || fail "opening the schema-9 database failed: $(cat "$WORK/out")"
[ "$(q "$D" "PRAGMA user_version")" -ge 10 ] || fail "not migrated"
after=$(q "$D" "SELECT key, dir, job_json, engine_version, lambda, dissipation_scale, seed, state, retries_used,
                       $OLD_COLS FROM jobs WHERE model = 'sp' ORDER BY key")
[ "$before" = "$after" ] || { diff <(echo "$before") <(echo "$after") >&2; fail "SP jobs' columns changed in the upgrade"; }
after_dp=$(q "$D" "SELECT key, $(echo "$OLD_COLS" | sed 's/E_sp, //') FROM jobs WHERE model <> 'sp' ORDER BY key")
[ "$before_dp" = "$after_dp" ] || { diff <(echo "$before_dp") <(echo "$after_dp") >&2; fail "DP jobs' columns changed"; }
[ "$(q "$D" "SELECT count(*) FROM jobs WHERE model <> 'sp' AND E_sp IS NULL")" -eq 4 ] || fail "a DP job's E_sp is not NULL"
after_runs=$(q "$D" "SELECT key, state, model, w, E_sp IS NOT NULL, seed, Q FROM runs ORDER BY key")
[ "$(echo "$before_runs" | sed 's/|dp_smooth|\([^|]*\)|1|/|dp_smooth|\1|0|/')" = "$after_runs" ] \
  || { diff <(echo "$before_runs") <(echo "$after_runs") >&2; fail "the runs view changed"; }
# stored: what is not a parameter, and the seed; everything else generated
stored=$(q "$D" "SELECT group_concat(name, ' ') FROM (SELECT name FROM pragma_table_xinfo('jobs') WHERE hidden = 0 ORDER BY cid)")
[ "$stored" = "key dir job_json engine_version lambda dissipation_scale seed state retries_used created_at" ] \
  || fail "stored jobs columns: $stored"
# the same columns as a campaign made at schema 10 from the start, with the same types
cols() { q "$1" "SELECT group_concat(name || ':' || type || ':' || hidden, ' ') FROM (SELECT * FROM pragma_table_xinfo('jobs') ORDER BY name)"; }
[ "$(cols "$D")" = "$(cols "$WORK/new")" ] || fail "upgraded jobs differ from new ones: $(cols "$D") vs $(cols "$WORK/new")"
for i in jobs_state jobs_physics jobs_dp_shape; do
  [ "$(q "$D" "SELECT count(*) FROM sqlite_master WHERE type = 'index' AND name = '$i'")" -eq 1 ] || fail "index $i missing"
done
[ "$(q "$D" "EXPLAIN QUERY PLAN SELECT key FROM jobs WHERE K_l = 10 AND K_b = 0.1" | grep -c jobs_dp_shape)" -ge 1 ] \
  || fail "the (K_l, K_b) index is not used"
[ -z "$(q "$D" "PRAGMA foreign_key_check")" ] || fail "dangling references after the upgrade"
[ "$(q "$D" "PRAGMA integrity_check")" = ok ] || fail "integrity_check after the upgrade"
[ "$(q "$D" "SELECT count(*) FROM velocity_profiles v JOIN jobs j ON j.key = v.job_key")" -eq 1 ] || fail "profiles lost their job"
# the store still inserts: the same sweep again links the 8 jobs (content-addressed), a new width adds 2 x 2 x 1
sed 's/\[4, 5.5\]/[4, 5.5, 7]/' "$WORK/sweep.json" > "$WORK/sweep2.json"
"$BIN" campaign create "$WORK/sweep2.json" --dir "$D" > /dev/null 2>&1 || fail "creating a campaign in the upgraded database failed"
[ "$(q "$D" "SELECT count(*) FROM jobs")" -eq 12 ] || fail "expected 12 jobs after adding w = 7: $(q "$D" "SELECT count(*) FROM jobs")"
[ "$(q "$D" "SELECT count(*) FROM jobs WHERE w = 7 AND state = 'pending' AND N = 40 AND seed IS NOT NULL")" -eq 4 ] \
  || fail "the new jobs' columns"
echo "ok  schema 9 -> $(q "$D" "PRAGMA user_version"): jobs rebuilt with generated parameter columns, every value and reference intact"
