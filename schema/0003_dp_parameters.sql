-- Deformable-particle (DP) models: their parameters as typed columns (NULL for SP jobs), and
-- the runs view with them. For DP jobs E_sp keeps the engine's unused default (the column is
-- NOT NULL since 0001); select on model or on these columns.
ALTER TABLE jobs ADD COLUMN n_v INTEGER;
ALTER TABLE jobs ADD COLUMN K_a REAL;
ALTER TABLE jobs ADD COLUMN K_l REAL;
ALTER TABLE jobs ADD COLUMN K_b REAL;
ALTER TABLE jobs ADD COLUMN E_c REAL;
CREATE INDEX jobs_dp_shape ON jobs (K_l, K_b);

DROP VIEW runs;
CREATE VIEW runs AS
SELECT j.key, j.dir, j.state, j.model, j.dimension, j.N, j.W_container, j.w, j.theta_w_left_deg, j.theta_w_right_deg,
       j.E_sp, j.E_w, j.zeta, j.mu, j.lambda, j.dissipation_scale, j.replica, j.seed,
       j.n_v, j.K_a, j.K_l, j.K_b, j.E_c,
       r.status, r.Q, r.Q_err, r.Q_rel_err, r.window_start, r.window_end, r.exits_in_window, r.clogged,
       r.clog_time, r.rho_n, r.Q_prime, r.mean_F_drag, r.mean_F_friction, r.force_ratio, r.dt,
       r.wall_seconds
FROM jobs j LEFT JOIN results r ON r.job_key = j.key;
