-- Fits of deformable-particle (DP) series: the model and its shape and contact parameters
-- (NULL for SP series), and E_sp NULL for DP series (it has no meaning there; 0002 made it
-- NOT NULL). beverloo_fit_results is rebuilt (SQLite cannot drop a NOT NULL in place); its rows
-- are kept as SP series. The views are dropped first, as a rename checks every view.
DROP VIEW beverloo_fits;

CREATE TABLE beverloo_fit_results_new (
  series_key      TEXT PRIMARY KEY,      -- sha256 of the canonical job without w, replica and seed
  label           TEXT NOT NULL,         -- e.g. "2D SP E_sp=100 lambda=inf", "2D DP smooth K_l=10 K_b=0.1 E_c=1e4 ..."
  model           TEXT NOT NULL,         -- sp, dp_smooth, dp_rough
  dimension       INTEGER NOT NULL,
  N               INTEGER NOT NULL,
  E_sp            REAL,                  -- SP only
  n_v             INTEGER,               -- DP only: vertices per polygon
  K_a             REAL,                  -- DP only
  K_l             REAL,                  -- DP only
  K_b             REAL,                  -- DP only
  E_c             REAL,                  -- DP only: vertex contact energy scale
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
INSERT INTO beverloo_fit_results_new (series_key, label, model, dimension, N, E_sp, zeta, mu, lambda, theta_w_left_deg,
                                      theta_w_right_deg, points, clogged_points, C, C_err, k, k_err, beta, beta_err,
                                      chi2_red, message, fitted_at)
SELECT series_key, label, 'sp', dimension, N, E_sp, zeta, mu, lambda, theta_w_left_deg, theta_w_right_deg, points,
       clogged_points, C, C_err, k, k_err, beta, beta_err, chi2_red, message, fitted_at FROM beverloo_fit_results;
DROP TABLE beverloo_fit_results;
ALTER TABLE beverloo_fit_results_new RENAME TO beverloo_fit_results;

CREATE VIEW beverloo_fits AS
SELECT label, model, dimension, N, E_sp, K_l, K_b, E_c, zeta, mu, lambda, theta_w_left_deg, theta_w_right_deg, points,
       clogged_points, C, C_err, k, k_err, beta, beta_err, chi2_red, message, n_v, K_a, series_key
FROM beverloo_fit_results ORDER BY dimension, model, E_sp, K_l, K_b, E_c, lambda;
