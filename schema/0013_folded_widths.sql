-- The authors' fits (bounded, and with beta held at d - 3/2 and d - 1/2) fit |C| |w - k|^beta, as
-- their MATLAB does: a k above some of the fitted widths folds those widths onto the law's mirror
-- image, where the law itself would give no flow. How many widths each fit folds (0: none; NULL:
-- no such fit). beverloo's free fit keeps k below every width and folds none. A held k that folds
-- a width measures the width range more than the orifice (docs/paper.md, Fig. 7a with the text's
-- model).
ALTER TABLE beverloo_fit_results ADD COLUMN authors_folded_points INTEGER;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_lo_folded_points INTEGER;
ALTER TABLE beverloo_fit_results ADD COLUMN authors_k_at_beta_hi_folded_points INTEGER;

DROP VIEW beverloo_fits_both_ways;
CREATE VIEW beverloo_fits_both_ways AS
SELECT label, dimension, N, lambda, points, beta, beta_err, replica_fits, beta_replica_spread, k, k_err, k_replica_spread,
       C, C_err, authors_points, authors_beta, authors_beta_err, authors_k, authors_k_err, authors_C, authors_C_err,
       authors_at_bound, authors_message, authors_folded_points, authors_k_at_beta_lo, authors_k_at_beta_lo_err,
       authors_k_at_beta_lo_replica_spread, authors_C_at_beta_lo, authors_k_at_beta_lo_folded_points,
       authors_k_at_beta_hi, authors_k_at_beta_hi_err, authors_k_at_beta_hi_replica_spread, authors_C_at_beta_hi,
       authors_k_at_beta_hi_folded_points, series_key
FROM beverloo_fit_results ORDER BY dimension, E_sp, lambda;
