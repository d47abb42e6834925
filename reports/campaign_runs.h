#pragma once
/// \file campaign_runs.h
/// \brief A campaign's finished jobs read from its database and grouped into series (every
/// parameter but w, the replica, the seed and run.min_time equal), labelled so that no two read
/// alike; the first step of `beverloo fit` (reports/campaign_fits.h).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "campaign_fits.h"

namespace beverloo {

/// One finished job as the fits need it.
struct RunRecord {
  double w = 0;
  int replica = 0;
  std::string seed;  ///< an explicit seed as the job gives it ("" when derived from the parameters)
  double Q = 0, Q_err = 0;
  bool clogged = false, time_limited = false;
  double clog_time = -1;  ///< the last exit before the clog (t0); -1 without a clog
  double end_time = 0;    ///< steps x dt: where the run ended (t0)
  double window_start = 0, window_end = 0;  ///< its measurement window (t0)
  double t_max = 0;       ///< its run.t_max
  double force_ratio = NAN;  ///< |F_zeta| / |F_mu| over its window (NaN: not stored)
  double force_ratio_err = NAN;  ///< its standard error over time blocks (NaN: an engine before the field)
};

struct CampaignRuns {
  std::vector<Series> series;                          ///< in the campaign's point order, labelled, not yet fitted
  std::map<std::string, std::vector<RunRecord>> runs;  ///< by series key, in point order
  std::map<std::string, nlohmann::json> base_job_of;   ///< series key -> its job without the dissipation parameters
};

/// The jobs with a result in the campaigns of `scope` (each job once), their points of `rate`.
CampaignRuns read_campaign_runs(db::Database& db, const CampaignScope& scope = CampaignScope::latest(), FlowRate rate = FlowRate::Q);
/// A job's series key: sha256 of its canonical JSON without w, the replica, the seed and
/// run.min_time.
std::string series_key_of(const nlohmann::json& job);

}  // namespace beverloo
