-- lambda_c without a sigmoid: where the group's measured exponents (free Beverloo fits, never
-- rescaled) cross d - 1, the paper's midpoint by construction, log10 lambda interpolated linearly
-- between the first bracketing pair of measured lambdas from below (crossing_lambda_lo, _hi).
-- Its sigma in log10 (decades) has three parts: the exponents' errors (crossing_log10_err), the
-- sample standard deviation of the replicas' own crossings (crossing_log10_replica_spread, over
-- crossing_replicas replicas that cross; NULL below two), and the interpolation's own error, how
-- far a parabola through the pair and a neighbouring lambda moves the crossing
-- (crossing_log10_interpolation; NULL without a neighbour). crossing_log10_sigma is what the
-- claims table and the Fig. 6 bars use: the larger of the first two with the third in
-- quadrature. All NULL when the exponents never cross d - 1 (docs/cli.md, reports/crossover_groups.h).
ALTER TABLE crossover_fit_results ADD COLUMN crossing_lambda REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_lambda_lo REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_lambda_hi REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_log10_err REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_log10_replica_spread REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_replicas INTEGER;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_log10_interpolation REAL;
ALTER TABLE crossover_fit_results ADD COLUMN crossing_log10_sigma REAL;

DROP VIEW crossover_fits_both_ways;
CREATE VIEW crossover_fits_both_ways AS
SELECT label, dimension, points, lambda_c, lambda_c_err, b, b_err, chi2_red,
       replica_fits, log10_lambda_c_replica_spread, b_replica_spread,
       free_lambda_c, free_lambda_c_err, free_b, free_b_err, free_beta_lambda0, free_beta_lambda0_err,
       free_beta_inf, free_beta_inf_err, free_chi2_red, free_message,
       free_replica_fits, free_log10_lambda_c_replica_spread, free_b_replica_spread,
       crossing_lambda, crossing_lambda_lo, crossing_lambda_hi, crossing_log10_err, crossing_log10_replica_spread,
       crossing_replicas, crossing_log10_interpolation, crossing_log10_sigma,
       beta_lambda0 AS measured_beta_lambda0, beta_lambda0_err AS measured_beta_lambda0_err,
       beta_inf AS measured_beta_inf, beta_inf_err AS measured_beta_inf_err, group_key
FROM crossover_fit_results ORDER BY dimension, label;
