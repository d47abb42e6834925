#pragma once
/// \file adaptive_spec.h
/// \brief A sweep's "adaptive" block (docs/sweeps.md, issue 30): what each Beverloo series of
/// the campaign wants from its fit, instead of (or on top of) the grid. The grid is the starting
/// design; the planner (reports/adaptive_planner.h) then adds one width at a time per series
/// where it reduces the variance of k and beta most per CPU (reports/next_width.h), until the
/// targets are met, the budget of added jobs is spent, or the series cannot be fitted.
///
///   "adaptive": {"target": {"k_err": 0.1, "beta_err": 0.05},   standard errors wanted (absolute)
///                "w_range": [3, 12], "w_step": 0.5,             candidate widths
///                "max_added_jobs": 20,                          per series
///                "extend": true}                                 also more flow time for a run
///
/// With "extend" a decision may also be more flow time for a finished run (its job with a
/// larger run.min_time, continuing its final checkpoint), chosen where that costs less per
/// information than a new run, whose transient and start the extension does not pay again.
///
/// With a "lambda" block the planner also grows each beta(lambda) group (series differing only
/// in lambda): once every series of the campaign is decided, it fits the crossover and adds a
/// whole new series (the grid's widths) at the lambda that most reduces the variance of
/// log10 lambda_c and b (reports/next_lambda.h), until those targets are met or the budget of
/// added series is spent:
///
///   "lambda": {"target": {"log10_lambda_c_err": 0.1, "b_err": 0.3},   standard errors wanted
///              "range": [1e-3, 10], "per_decade": 4,                    candidate lambdas
///              "max_added_series": 4}                                   per group
///
/// A third target, "crossing_interpolation_err" (decades), needs no sigmoid: where the group's
/// measured exponents cross d - 1 (reports/crossover_groups.h, MidpointCrossing), a new series
/// goes at the candidate lambda nearest that crossing, inside its bracketing pair, until the
/// chord's interpolation error (a parabola through a neighbouring lambda) is at most the target
/// or no candidate is left inside the bracket. It is met before the sigmoid's targets are pursued.
///
/// The budget is a number of jobs, not CPU hours: CPU time differs between machines and runs,
/// and the same results must always give the same decisions.
#include <optional>

#include <nlohmann/json.hpp>

namespace beverloo {

struct LambdaAdaptiveSpec {
  std::optional<double> log10_lambda_c_err, b_err;
  std::optional<double> crossing_interpolation_err;  ///< decades; see above
  double lambda_lo = 0, lambda_hi = 0;
  int per_decade = 4;
  int max_added_series = 4;
};

struct AdaptiveSpec {
  std::optional<double> k_err, beta_err;
  double w_lo = 0, w_hi = 0, w_step = 0.5;
  int max_added_jobs = 20;
  bool extend = false;  ///< also more flow time for finished runs (reports/next_width.h)
  std::optional<LambdaAdaptiveSpec> lambda;  ///< grow the beta(lambda) groups too

  /// Parses and checks the block (SweepError naming "adaptive.<field>").
  static AdaptiveSpec parse(const nlohmann::json& block);
  /// The block of a sweep's JSON, if it has one.
  static std::optional<AdaptiveSpec> of_sweep(const nlohmann::json& sweep);
};

}  // namespace beverloo
