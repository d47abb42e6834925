-- The run-to-run spread of the offset k, beside beta's (schema 0007): each replica (seed) with
-- every width of the pooled fit fitted alone, the sample standard deviation of its k in the free
-- fit and in the authors' fits with beta held at d - 3/2 (lo) and d - 1/2 (hi); NULL below two
-- such replicas. The paper's Fig. 7 maps k, and a difference between two of its cells is judged
-- by this spread as much as by a fit's error (docs/paper.md).
ALTER TABLE beverloo_fit_results ADD COLUMN k_replica_spread REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_lo_replica_spread REAL;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_hi_replica_spread REAL;

DROP VIEW beverloo_fits_both_ways;
CREATE VIEW beverloo_fits_both_ways AS
SELECT label, dimension, N, lambda, points, beta, beta_err, replica_fits, beta_replica_spread, k, k_err, k_replica_spread,
       C, C_err, authors_points, authors_beta, authors_beta_err, authors_k, authors_k_err, authors_C, authors_C_err,
       authors_at_bound, authors_message, authors_k_at_beta_lo, authors_k_at_beta_lo_err,
       authors_k_at_beta_lo_replica_spread, authors_C_at_beta_lo, authors_k_at_beta_hi, authors_k_at_beta_hi_err,
       authors_k_at_beta_hi_replica_spread, authors_C_at_beta_hi, series_key
FROM beverloo_fit_results ORDER BY dimension, E_sp, lambda;
