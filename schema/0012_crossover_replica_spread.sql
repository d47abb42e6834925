-- The run-to-run spread of the crossover beta(lambda), beside the exponents' (schema 0007, 0011):
-- the sigmoid fitted again to each replica's own exponents (the replicas with a free Beverloo fit
-- in every finite-lambda series of the group, over the pooled fit's lambdas), the sample standard
-- deviation of log10 lambda_c and of b over those fits; NULL below two. replica_fits counts the
-- replicas whose own crossover fit succeeded. The same for the fit with free plateaus (free_*).
-- lambda_c is fitted and judged in log10 (docs/paper.md), so its spread is in decades.
ALTER TABLE crossover_fit_results ADD COLUMN replica_fits INTEGER;
ALTER TABLE crossover_fit_results ADD COLUMN log10_lambda_c_replica_spread REAL;
ALTER TABLE crossover_fit_results ADD COLUMN b_replica_spread REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_replica_fits INTEGER;
ALTER TABLE crossover_fit_results ADD COLUMN free_log10_lambda_c_replica_spread REAL;
ALTER TABLE crossover_fit_results ADD COLUMN free_b_replica_spread REAL;

DROP VIEW crossover_fits_both_ways;
CREATE VIEW crossover_fits_both_ways AS
SELECT label, dimension, points, lambda_c, lambda_c_err, b, b_err, chi2_red,
       replica_fits, log10_lambda_c_replica_spread, b_replica_spread,
       free_lambda_c, free_lambda_c_err, free_b, free_b_err, free_beta_lambda0, free_beta_lambda0_err,
       free_beta_inf, free_beta_inf_err, free_chi2_red, free_message,
       free_replica_fits, free_log10_lambda_c_replica_spread, free_b_replica_spread,
       beta_lambda0 AS measured_beta_lambda0, beta_lambda0_err AS measured_beta_lambda0_err,
       beta_inf AS measured_beta_inf, beta_inf_err AS measured_beta_inf_err, group_key
FROM crossover_fit_results ORDER BY dimension, label;
