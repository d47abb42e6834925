#pragma once
/// \file next_width.h
/// \brief Where the next run of a Beverloo series helps the fit most per CPU (issue 30 item 1:
/// the design criterion; reports/adaptive_planner.h adds such jobs while a campaign runs).
///
/// The criterion: A-optimality on the parameters users quote, k and beta (not C), per unit of
/// cost. With the fit's Fisher information F = sum_i g_i g_i^T / sigma_i^2 (g = dQ/d(C, k, beta)
/// at the fitted values; F^-1 is the covariance the fit reports, not rescaled by chi^2), a new
/// run at width w run to the series' typical relative error r adds g(w) g(w)^T / (r Q(w))^2.
/// phi = Var(k) / s_k^2 + Var(beta) / s_beta^2 with s the targets (or, without targets, the
/// present errors: the relative reduction of both), and a run at w costs CPU ~ 1 / (r^2 Q(w))
/// (the exits needed for r over the flow rate), so the choice is the w of largest
/// (phi_now - phi_after) Q(w). D-optimality (det F) would spend runs on C, which nobody quotes;
/// near k runs are informative but slow, and the cost term weighs exactly that. Deterministic:
/// candidates on a fixed grid, ties to the smaller w.
#include <optional>
#include <string>
#include <vector>

#include "fit.h"

namespace beverloo {

struct DesignTargets {
  std::optional<double> k_err, beta_err;  ///< standard errors wanted (absolute); unset: no target
};

/// More flow time for finished runs (the sweep's "adaptive.extend"): the costs in t0 of flow that
/// compare it with a new run. Extending a run by its own window adds what a run of its error
/// adds (the pooled points weigh by inverse variance, and a window twice as long halves the
/// variance), at the cost of that window alone; a new run also pays its start (the transient
/// before its window). Within a series the CPU per t0 is about the same at every width.
struct FlowTimeCosts {
  double start_t0 = 0;         ///< a new run's flow before its window opens (the series' median)
  double exits_rel2 = 0;       ///< median of window x Q x (SE/Q)^2 over the series' runs: a window
                               ///< of exits_rel2 / (r^2 Q) gives the relative error r
  struct Run {
    double w = 0, Q_err = 0;   ///< its width and own standard error
    double window_t0 = 0;      ///< its measurement window: the extension's length and cost
  };
  std::vector<Run> runs;       ///< the runs that may be extended (flowing, with an error)
};

struct NextWidth {
  double w = 0;                               ///< the suggested width
  double k_err_after = 0, beta_err_after = 0;  ///< predicted standard errors with that run added
  double relative_cost = 0;                   ///< its CPU over that of a run at the series' median Q
  /// With FlowTimeCosts: the run of FlowTimeCosts::runs to give more flow time (its window
  /// again) instead of a new run at w; unset: a new run.
  std::optional<std::size_t> extend_run;
};

struct DesignAdvice {
  double k_err_now = 0, beta_err_now = 0;  ///< from the Fisher information (the fit's errors)
  bool targets_met = false;                ///< every target given is met (false without targets)
  std::optional<NextWidth> next;           ///< unset when the targets are met
};

/// points: the flowing points of the series (w, Q, Q_err > 0) the fit was made from; candidates
/// w_lo, w_lo + step, ... <= w_hi, those at or below k + step left out (no flow there).
/// Throws FitError when no candidate is left or the information is singular.
/// costs (optional): also consider more flow time for the runs it lists, and price a new run
/// with its start (cost in t0: start_t0 + exits_rel2 / (r^2 Q(w))); a tie goes to the new run.
DesignAdvice next_width(const BeverlooFit& fit, const std::vector<double>& w, const std::vector<double>& Q,
                        const std::vector<double>& Q_err, double w_lo, double w_hi, double step,
                        const DesignTargets& targets = {}, const FlowTimeCosts* costs = nullptr);

}  // namespace beverloo
