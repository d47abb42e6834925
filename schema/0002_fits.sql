-- beverloo campaign store, migration 2: fits (written by `beverloo fit`, replaced on every fit).

-- One row per series: every parameter but w equal; replicas pooled.
CREATE TABLE beverloo_fit_results (
  series_key      TEXT PRIMARY KEY,      -- sha256 of the canonical job without w, replica and seed
  label           TEXT NOT NULL,         -- e.g. "2D SP E_sp=100 lambda=inf"
  dimension       INTEGER NOT NULL,
  N               INTEGER NOT NULL,
  E_sp            REAL NOT NULL,
  zeta            REAL NOT NULL,
  mu              REAL NOT NULL,
  lambda          REAL,
  theta_w_left_deg  REAL NOT NULL,
  theta_w_right_deg REAL NOT NULL,
  points          INTEGER NOT NULL,      -- flowing w values used
  clogged_points  INTEGER NOT NULL,      -- w values left out because every replica clogged
  C REAL, C_err REAL, k REAL, k_err REAL, beta REAL, beta_err REAL, chi2_red REAL,
  message         TEXT,                  -- why there is no fit (too few points, ...), else NULL
  fitted_at       TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

-- The pooled points behind each series fit.
CREATE TABLE series_points (
  series_key  TEXT NOT NULL REFERENCES beverloo_fit_results (series_key),
  w           REAL NOT NULL,
  Q           REAL NOT NULL,             -- inverse-variance mean over flowing replicas (0 if clogged)
  Q_err       REAL NOT NULL,
  replicas    INTEGER NOT NULL,
  clogged     INTEGER NOT NULL,          -- replicas that clogged
  PRIMARY KEY (series_key, w)
);

-- One row per group of series that differ only in lambda = zeta/mu.
CREATE TABLE crossover_fit_results (
  group_key        TEXT PRIMARY KEY,
  label            TEXT NOT NULL,
  dimension        INTEGER NOT NULL,
  points           INTEGER NOT NULL,     -- finite lambda > 0 with a fitted beta
  lambda_c REAL, lambda_c_err REAL, b REAL, b_err REAL, chi2_red REAL,
  beta_lambda0     REAL,                 -- the limits, from the lambda = 0 and lambda = inf series
  beta_lambda0_err REAL,
  beta_inf         REAL,
  beta_inf_err     REAL,
  message          TEXT,
  fitted_at        TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE VIEW beverloo_fits AS
SELECT label, dimension, N, E_sp, zeta, mu, lambda, theta_w_left_deg, theta_w_right_deg, points, clogged_points,
       C, C_err, k, k_err, beta, beta_err, chi2_red, message, series_key
FROM beverloo_fit_results ORDER BY dimension, E_sp, lambda;

CREATE VIEW crossover_fits AS
SELECT label, dimension, points, lambda_c, lambda_c_err, b, b_err, chi2_red, beta_lambda0, beta_lambda0_err,
       beta_inf, beta_inf_err, message, group_key
FROM crossover_fit_results ORDER BY dimension, label;
