-- Draining-hopper measurements beside the simulations (issue 17, docs/experiments.md): droplet
-- exit times per run, imported by `beverloo experiment import` from CSV in SI units, each run's
-- fit of dN/dt = -c0 sqrt(N) (engine/protocol/drain_fit) and its Q = c0 t0 with
-- t0 = sqrt(sigma_avg / g_eff). A series is one imported file; its provenance says whether it
-- was measured or made by beverloo from a simulated drain (then labelled so everywhere).
CREATE TABLE experiment_series (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL UNIQUE,
  provenance    TEXT NOT NULL CHECK (provenance IN ('measured', 'simulated')),
  source        TEXT NOT NULL,          -- free text from the file: who, where, which apparatus or job
  geometry      TEXT NOT NULL,          -- free text, e.g. "45/45" (wall angles from gravity, degrees)
  sigma_avg_m   REAL NOT NULL CHECK (sigma_avg_m > 0),   -- mean droplet diameter, metres
  g_eff_m_s2    REAL NOT NULL CHECK (g_eff_m_s2 > 0),    -- effective gravity, m/s^2
  t0_s          REAL NOT NULL CHECK (t0_s > 0),          -- sqrt(sigma_avg / g_eff), seconds
  fit_skip      INTEGER NOT NULL,       -- exits left out at each end of every run's fit
  block_exits   INTEGER NOT NULL,       -- exits per rate block
  file_name     TEXT NOT NULL,
  file_sha256   TEXT NOT NULL,
  imported_at   TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE experiment_runs (
  id            INTEGER PRIMARY KEY,
  series_id     INTEGER NOT NULL REFERENCES experiment_series(id) ON DELETE CASCADE,
  run           TEXT NOT NULL,          -- the run's name in the file
  w_m           REAL NOT NULL CHECK (w_m > 0),   -- orifice width, metres
  w             REAL NOT NULL,          -- orifice width in sigma_avg
  n_initial     INTEGER NOT NULL,       -- droplets in the hopper at the first time
  exits         INTEGER NOT NULL,
  duration_s    REAL NOT NULL,
  c0_per_s      REAL,                   -- NULL when the run could not be fitted
  c0_err_per_s  REAL,
  Q             REAL,                   -- c0 t0 (the paper's dimensionless Q of a draining hopper)
  Q_err         REAL,
  chi2_red      REAL,
  blocks        INTEGER,
  message       TEXT,                   -- why there is no fit, else NULL
  UNIQUE (series_id, run)
);

CREATE TABLE experiment_exits (
  run_id        INTEGER NOT NULL REFERENCES experiment_runs(id) ON DELETE CASCADE,
  k             INTEGER NOT NULL,       -- 0, 1, ...: the k-th exit of the run
  t_s           REAL NOT NULL,          -- seconds from the run's first recorded time
  PRIMARY KEY (run_id, k)
) WITHOUT ROWID;

CREATE TABLE experiment_fit_results (
  series_id     INTEGER PRIMARY KEY REFERENCES experiment_series(id) ON DELETE CASCADE,
  label         TEXT NOT NULL,
  points        INTEGER NOT NULL,       -- orifice widths fitted (runs at one width pooled)
  C REAL, C_err REAL, k REAL, k_err REAL, beta REAL, beta_err REAL, chi2_red REAL,
  message       TEXT,
  fitted_at     TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

-- One row per run, with its series: what `query` users compare with the runs view.
CREATE VIEW experiment_results AS
SELECT s.name AS series, s.provenance, s.geometry, r.run, r.w, r.w_m, s.sigma_avg_m, s.g_eff_m_s2, s.t0_s,
       r.n_initial, r.exits, r.duration_s, r.c0_per_s, r.c0_err_per_s, r.Q, r.Q_err, r.chi2_red, r.blocks, r.message
FROM experiment_runs r JOIN experiment_series s ON s.id = r.series_id;
