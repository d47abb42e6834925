-- Every job parameter's column is generated from the stored canonical job (issue 28): the
-- columns schemas 0001 and 0003 stored (model, dimension, N, size_ratio, W_container, w,
-- theta_w_*_deg, E_sp, E_w, zeta, mu, gravity, replica, t_max, target_rel_err, n_v, K_a, K_l,
-- K_b, E_c) become VIRTUAL generated columns over job_json like every parameter added since
-- 0005. This migration keeps what is not a parameter, or cannot be read back from the job:
--   key, dir, job_json, engine_version, state, retries_used, created_at;
--   lambda and dissipation_scale (derived from zeta and mu; lambda = +inf is stored as 9e999);
--   seed (the seed the run uses: a hash of the job when the job gives none).
-- The store (orchestrator/db/typed_columns.cpp) then adds one generated column per parameter
-- row with an SQL column, with the same names and types as before, and the indexes over them
-- (jobs_physics, jobs_dp_shape), in the same transaction. What a query sees changes in one
-- place: E_sp of a DP job is NULL (the canonical DP job does not carry it; it was the unused
-- default), as the DP columns are NULL for an SP job.
--
-- SQLite cannot drop columns that other schema objects use, so the table is rebuilt (its
-- documented 12-step procedure; open_store runs migrations with foreign keys off and checks
-- them before committing). The runs view is dropped here and rebuilt by the store right after;
-- legacy_alter_table keeps the RENAME from re-parsing views a user may have added over jobs
-- (between the DROP and the store's step they name columns that do not exist yet, and SQLite
-- would refuse the rename; they work again once the columns are back).
-- A later migration must not read a parameter column of jobs: those exist only after the store's
-- step, which runs after every migration.

CREATE TABLE jobs_new (
  key                TEXT PRIMARY KEY,    -- sha256 of the canonical job + engine version
  dir                TEXT NOT NULL UNIQUE,-- jobs/<first 16 hex of key>
  job_json           TEXT NOT NULL,       -- canonical resolved job (what the engine runs)
  engine_version     TEXT NOT NULL,
  lambda             REAL,                -- zeta/mu; +inf (9e999) when mu = 0; NULL when both are 0
  dissipation_scale  REAL,                -- sqrt(zeta*mu) when both > 0, else the nonzero one
  seed               INTEGER NOT NULL,    -- the seed the run uses (derived when the job gives none)
  state              TEXT NOT NULL DEFAULT 'pending'
                     CHECK (state IN ('pending', 'running', 'done', 'clogged', 'failed', 'cancelled')),
  retries_used       INTEGER NOT NULL DEFAULT 0,   -- science retries (infrastructure ones are free)
  created_at         TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);
INSERT INTO jobs_new (key, dir, job_json, engine_version, lambda, dissipation_scale, seed, state, retries_used, created_at)
  SELECT key, dir, job_json, engine_version, lambda, dissipation_scale, seed, state, retries_used, created_at FROM jobs;
DROP VIEW IF EXISTS runs;
DROP TABLE jobs;
PRAGMA legacy_alter_table = ON;
ALTER TABLE jobs_new RENAME TO jobs;
PRAGMA legacy_alter_table = OFF;
CREATE INDEX jobs_state ON jobs (state);
