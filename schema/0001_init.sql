-- beverloo campaign store, migration 1. Append-only: never edit a shipped migration; add 0002_*.sql.
-- Only the coordinator writes this database; workers write only their job directories.

CREATE TABLE campaigns (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL,
  sweep_json    TEXT NOT NULL,            -- the sweep file as given
  sweep_sha256  TEXT NOT NULL,
  created_at    TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  UNIQUE (name, sweep_sha256)
);

-- One row per distinct job (content-addressed): shared by every campaign that contains it.
CREATE TABLE jobs (
  key                TEXT PRIMARY KEY,    -- sha256 of the canonical job + engine version
  dir                TEXT NOT NULL UNIQUE,-- jobs/<first 16 hex of key>
  job_json           TEXT NOT NULL,       -- canonical resolved job (what the engine runs)
  engine_version     TEXT NOT NULL,
  model              TEXT NOT NULL,
  dimension          INTEGER NOT NULL,
  N                  INTEGER NOT NULL,
  size_ratio         REAL NOT NULL,
  W_container        REAL NOT NULL,       -- the container width W (SQLite names ignore case: w is the orifice)
  w                  REAL NOT NULL,
  theta_w_left_deg   REAL NOT NULL,
  theta_w_right_deg  REAL NOT NULL,
  E_sp               REAL NOT NULL,
  E_w                REAL NOT NULL,
  zeta               REAL NOT NULL,
  mu                 REAL NOT NULL,
  lambda             REAL,                -- zeta/mu; +inf (9e999) when mu = 0; NULL when both are 0
  dissipation_scale  REAL,                -- sqrt(zeta*mu) when both > 0, else the nonzero one
  gravity            REAL NOT NULL,
  replica            INTEGER NOT NULL,
  seed               INTEGER NOT NULL,
  t_max              REAL NOT NULL,
  target_rel_err     REAL NOT NULL,
  state              TEXT NOT NULL DEFAULT 'pending'
                     CHECK (state IN ('pending', 'running', 'done', 'clogged', 'failed', 'cancelled')),
  retries_used       INTEGER NOT NULL DEFAULT 0,   -- science retries (infrastructure ones are free)
  created_at         TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);
CREATE INDEX jobs_state ON jobs (state);
CREATE INDEX jobs_physics ON jobs (dimension, lambda, w);

CREATE TABLE campaign_jobs (
  campaign_id  INTEGER NOT NULL REFERENCES campaigns (id),
  job_key      TEXT NOT NULL REFERENCES jobs (key),
  point_index  INTEGER NOT NULL,          -- position in the sweep's expansion
  sweep_point  TEXT NOT NULL,             -- the point's own parameters (incl. lambda, replica) as JSON
  PRIMARY KEY (campaign_id, job_key)
);

CREATE TABLE attempts (
  id             INTEGER PRIMARY KEY,
  job_key        TEXT NOT NULL REFERENCES jobs (key),
  attempt_no     INTEGER NOT NULL,
  token          TEXT NOT NULL UNIQUE,    -- fencing: a result is ingested only with its attempt's token
  executor       TEXT NOT NULL,           -- 'local' (later 'slurm')
  host           TEXT,
  pid            INTEGER,
  state          TEXT NOT NULL CHECK (state IN ('running', 'succeeded', 'failed', 'lost', 'interrupted')),
  started_at     TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  heartbeat_at   TEXT,
  ended_at       TEXT,
  exit_status    INTEGER,                 -- worker exit code (or 128 + signal)
  failure_class  TEXT CHECK (failure_class IN ('invalid_parameters', 'blow_up', 'killed', 'timeout', 'io',
                                               'interrupted', 'lost', 'internal')),
  message        TEXT,
  UNIQUE (job_key, attempt_no)
);
CREATE INDEX attempts_state ON attempts (state);

CREATE TABLE results (
  job_key             TEXT PRIMARY KEY REFERENCES jobs (key),
  attempt_id          INTEGER NOT NULL REFERENCES attempts (id),
  status              TEXT NOT NULL,      -- converged | time_limit | clogged
  Q                   REAL NOT NULL,
  Q_err               REAL NOT NULL,
  Q_rel_err           REAL NOT NULL,
  window_start        REAL NOT NULL,
  window_end          REAL NOT NULL,
  exits_in_window     INTEGER NOT NULL,
  exits_total         INTEGER NOT NULL,
  clogged             INTEGER NOT NULL,
  clog_time           REAL,
  rho_n               REAL,
  a_eff               REAL,
  Q_prime             REAL,
  Q_prime_err         REAL,
  mean_F_drag         REAL,
  mean_F_friction     REAL,
  force_ratio         REAL,
  dt                  REAL NOT NULL,
  steps               INTEGER NOT NULL,
  wall_seconds        REAL NOT NULL,
  particle_steps_per_second REAL,
  summary_json        TEXT NOT NULL,
  ingested_at         TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE velocity_profiles (
  job_key  TEXT NOT NULL REFERENCES jobs (key),
  h        REAL NOT NULL,
  v_g      REAL NOT NULL,
  v_g_err  REAL NOT NULL,
  PRIMARY KEY (job_key, h)
);

-- For people: parameters and results side by side, one row per job.
CREATE VIEW runs AS
SELECT j.key, j.dir, j.state, j.model, j.dimension, j.N, j.W_container, j.w, j.theta_w_left_deg, j.theta_w_right_deg,
       j.E_sp, j.E_w, j.zeta, j.mu, j.lambda, j.dissipation_scale, j.replica, j.seed,
       r.status, r.Q, r.Q_err, r.Q_rel_err, r.window_start, r.window_end, r.exits_in_window, r.clogged,
       r.clog_time, r.rho_n, r.Q_prime, r.mean_F_drag, r.mean_F_friction, r.force_ratio, r.dt,
       r.wall_seconds
FROM jobs j LEFT JOIN results r ON r.job_key = j.key;
