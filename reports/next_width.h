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

struct NextWidth {
  double w = 0;                               ///< the suggested width
  double k_err_after = 0, beta_err_after = 0;  ///< predicted standard errors with that run added
  double relative_cost = 0;                   ///< its CPU over that of a run at the series' median Q
};

struct DesignAdvice {
  double k_err_now = 0, beta_err_now = 0;  ///< from the Fisher information (the fit's errors)
  bool targets_met = false;                ///< every target given is met (false without targets)
  std::optional<NextWidth> next;           ///< unset when the targets are met
};

/// points: the flowing points of the series (w, Q, Q_err > 0) the fit was made from; candidates
/// w_lo, w_lo + step, ... <= w_hi, those at or below k + step left out (no flow there).
/// Throws FitError when no candidate is left or the information is singular.
DesignAdvice next_width(const BeverlooFit& fit, const std::vector<double>& w, const std::vector<double>& Q,
                        const std::vector<double>& Q_err, double w_lo, double w_hi, double step,
                        const DesignTargets& targets = {});

}  // namespace beverloo
