#pragma once
/// \file next_lambda.h
/// \brief Where a new lambda series helps the crossover fit most (issue 30: "the same for
/// lambda_c and the sigmoid's width"; reports/adaptive_planner.h adds such series).
///
/// The law is the paper's, with its plateaus fixed: beta(lambda) = d - 1 - tanh(u)/2, u =
/// (log10 lambda - x)/b, x = log10 lambda_c. Its Fisher information on (x, b) from the group's
/// series is F = sum_i g_i g_i^T / sigma_i^2, g = dbeta/d(x, b) = (sech^2 u / 2b) (1, u). A new
/// series at lambda, fitted to the group's median beta error sigma_new, adds g g^T / sigma_new^2.
/// The criterion is A-optimal on what users quote: phi = Var(x)/s_x^2 + Var(b)/s_b^2 with s the
/// targets (a parameter without a target: its present error, so its relative reduction counts),
/// and the candidate of largest phi_now - phi_after wins. No cost weight, unlike next_width:
/// along the paper's axes every series costs about the same (the same widths and error target;
/// measured on Fig. 4a's grid, 1090-2090 t0 per series of 8 widths). Raising the drag beyond
/// the grid costs more (Q falls as 1/drag), which is why lambda_series.h lowers the friction there. The information
/// of a point peaks where the sigmoid is steep (|u| < 1): runs go where lambda_c is decided.
/// Predicted errors are scaled by the fit's reported error over the Fisher one (the fit's errors
/// may include its chi^2). A step so sharp that no series sits on it leaves the information
/// singular: then the free candidate nearest the fitted lambda_c, with no prediction (NaN).
/// Deterministic: candidates on a fixed log grid, ties to the smaller.
#include <optional>
#include <vector>

#include "fit.h"

namespace beverloo {

struct CrossoverTargets {
  std::optional<double> log10_lambda_c_err, b_err;  ///< standard errors wanted; unset: no target
};

struct NextLambda {
  double lambda = 0;
  double log10_lambda_c_err_after = 0, b_err_after = 0;  ///< predicted with that series added
};

struct CrossoverAdvice {
  double log10_lambda_c_err_now = 0, b_err_now = 0;  ///< the fit's
  bool targets_met = false;                          ///< every target given is met (false without)
  std::optional<NextLambda> next;                    ///< unset when the targets are met
};

/// The candidate lambdas of a group, in log10 and ascending: k / per_decade (from the index, so
/// the same grid every time) within [lambda_lo, lambda_hi], leaving out those within half a step
/// of a lambda in `have` (the group's series; non-positive or infinite ones ignored). Throws
/// FitError for a bad range or more than 100000 candidates.
std::vector<double> free_candidate_log10_lambdas(const std::vector<double>& have, double lambda_lo, double lambda_hi,
                                                 int per_decade);

/// lambda, beta_err: the group's finite series (beta_err > 0). Candidates: per_decade points per
/// decade on [lambda_lo, lambda_hi] (at 10^(k/per_decade)), leaving out those within half a
/// step (in log10) of a series the group has. Throws FitError when no candidate is left.
CrossoverAdvice next_lambda(int dimension, const CrossoverFit& fit, const std::vector<double>& lambda,
                            const std::vector<double>& beta_err, double lambda_lo, double lambda_hi, int per_decade,
                            const CrossoverTargets& targets = {});

}  // namespace beverloo
