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
///                "max_added_jobs": 20}                          per series
///
/// The budget is a number of jobs, not CPU hours: CPU time differs between machines and runs,
/// and the same results must always give the same decisions.
#include <optional>

#include <nlohmann/json.hpp>

namespace beverloo {

struct AdaptiveSpec {
  std::optional<double> k_err, beta_err;
  double w_lo = 0, w_hi = 0, w_step = 0.5;
  int max_added_jobs = 20;

  /// Parses and checks the block (SweepError naming "adaptive.<field>").
  static AdaptiveSpec parse(const nlohmann::json& block);
  /// The block of a sweep's JSON, if it has one.
  static std::optional<AdaptiveSpec> of_sweep(const nlohmann::json& sweep);
};

}  // namespace beverloo
