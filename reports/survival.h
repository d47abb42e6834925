#pragma once
/// \file survival.h
/// \brief Clogging as a measured result (issue 30): the time to a clog from replicas, with the
/// runs that ended without clogging censored at their end, by the Kaplan-Meier product-limit
/// estimator and Greenwood's variance (e.g. Kalbfleisch & Prentice, The Statistical Analysis of
/// Failure Time Data, sections 1.4 and 4.3).
#include <vector>

namespace beverloo {

struct SurvivalObservation {
  double time = 0;      ///< t0: the clog (the last exit before it), or the run's end
  bool clogged = false; ///< false: censored (the run ended flowing)
};

struct KaplanMeier {
  int runs = 0, clogs = 0;
  /// The steps of S(t): after time[i], S = survival[i] +- survival_err[i] (Greenwood); S = 1 before time[0].
  std::vector<double> time, survival, survival_err;
  /// S at t (1 before the first clog); its Greenwood error.
  double at(double t) const;
  double err_at(double t) const;
  /// The first time at which S falls to 1/2 or below; NaN if it never does within the data.
  double median() const;
};

/// Ties: clogs at one time are one step; a run censored at a clog's time counts as still at
/// risk then (the usual convention). Empty input gives runs = 0 and S = 1.
KaplanMeier kaplan_meier(std::vector<SurvivalObservation> obs);

}  // namespace beverloo
