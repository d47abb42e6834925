#pragma once
/// \file series_fits.h
/// \brief One series' fits from its runs: the pooled points (replicas by inverse-variance
/// weights, clogged ones counted apart), the Beverloo fit, the run-to-run spread of beta over
/// replicas, the authors' bounded fit beside it, and the clog statistics per w.
#include <vector>

#include "campaign_runs.h"

namespace beverloo {

void fit_series(Series& s, const std::vector<RunRecord>& runs);

/// The mean (NaN without values).
double sample_mean(const std::vector<double>& v);
/// The sample standard deviation (NaN below two values).
double sample_sd(const std::vector<double>& v);

}  // namespace beverloo
