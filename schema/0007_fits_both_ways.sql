-- Every exponent fitted two ways (issue 32, docs/paper.md): beverloo's free fit (the default,
-- the columns above) and the way the paper's authors fitted theirs: unweighted least squares
-- within bounds (beta 0.4 .. 1.58, k 0.5 .. 5, C 0 .. 1 of their flow unit = 316.4
-- sigma_avg^2/t0) over the widths 2 < w < 19 (reports/fit.h, BoundedFitOptions::authors).
-- authors_at_bound names the parameters that ended on a bound ("beta", "k,beta", ...; '' none).
ALTER TABLE beverloo_fit_results ADD COLUMN authors_C REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_C_err REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_err REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_beta REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_beta_err REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_points INTEGER;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_at_bound TEXT;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_message TEXT;   -- why there is no such fit
-- the authors' fits with beta held fixed (their Fig. 2 and Appendix B: fitmodes 1 and 2), at
-- beta = d - 3/2 (lo) and d - 1/2 (hi): unweighted, points with Q > 0.01 of their flow unit only
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_lo REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_lo_err REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_C_at_beta_lo REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_hi REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_hi_err REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_C_at_beta_hi REAL;
-- the run-to-run spread: each replica (seed) fitted alone (those with every width of the pooled
-- fit), and the sample standard deviation of their betas (NULL below two replicas)
ALTER TABLE beverloo_fit_results ADD COLUMN replica_fits INTEGER;
ALTER TABLE beverloo_fit_results ADD COLUMN beta_replica_spread REAL;

-- The crossover beta(lambda) also with its plateaus free (the paper fixes them at d - 1/2 and
-- d - 3/2): beta_lambda0 and beta_inf are then fitted, beside the limits' own measured fits.
ALTER TABLE crossover_fit_results ADD COLUMN free_lambda_c REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_lambda_c_err REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_b REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_b_err REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_beta_lambda0 REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_beta_lambda0_err REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_beta_inf REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_beta_inf_err REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_chi2_red REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_message TEXT;

CREATE VIEW beverloo_fits_both_ways AS
SELECT label, dimension, N, lambda, points, beta, beta_err, replica_fits, beta_replica_spread, k, k_err, C, C_err,
       authors_points, authors_beta, authors_beta_err, authors_k, authors_k_err, authors_C, authors_C_err,
       authors_at_bound, authors_message, authors_k_at_beta_lo, authors_k_at_beta_lo_err, authors_C_at_beta_lo,
       authors_k_at_beta_hi, authors_k_at_beta_hi_err, authors_C_at_beta_hi, series_key
FROM beverloo_fit_results ORDER BY dimension, E_sp, lambda;

CREATE VIEW crossover_fits_both_ways AS
SELECT label, dimension, points, lambda_c, lambda_c_err, b, b_err, chi2_red,
       free_lambda_c, free_lambda_c_err, free_b, free_b_err, free_beta_lambda0, free_beta_lambda0_err,
       free_beta_inf, free_beta_inf_err, free_chi2_red, free_message,
       beta_lambda0 AS measured_beta_lambda0, beta_lambda0_err AS measured_beta_lambda0_err,
       beta_inf AS measured_beta_inf, beta_inf_err AS measured_beta_inf_err, group_key
FROM crossover_fit_results ORDER BY dimension, label;

-- Clogging as a result (issue 30): per series and w, the time to a clog over the replicas by the
-- Kaplan-Meier estimator, runs that ended flowing censored at their end (steps x dt); written
-- by `beverloo fit` for every w of a series in which some run clogged (reports/survival.h).
CREATE TABLE clog_survival (
  series_key   TEXT NOT NULL,
  label        TEXT NOT NULL,
  w            REAL NOT NULL,
  runs         INTEGER NOT NULL,   -- replicas with a result at this w
  clogs        INTEGER NOT NULL,
  t_max        REAL NOT NULL,      -- run.t_max of these jobs (t0)
  p_clog       REAL NOT NULL,      -- 1 - S(t_max): the probability to clog within t_max
  p_clog_err   REAL NOT NULL,      -- Greenwood's standard error
  median_time  REAL,               -- first t with S(t) <= 1/2 (t0); NULL if S stays above
  km_time      TEXT NOT NULL,      -- JSON arrays: the steps of S(t) and their errors
  km_survival  TEXT NOT NULL,
  km_survival_err TEXT NOT NULL,
  PRIMARY KEY (series_key, w)
);
CREATE VIEW clog_statistics AS
SELECT label, w, runs, clogs, t_max, p_clog, p_clog_err, median_time, series_key
FROM clog_survival ORDER BY label, w;
