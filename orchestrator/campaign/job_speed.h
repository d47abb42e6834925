#pragma once
/// \file job_speed.h
/// \brief How fast a campaign's jobs ran, in the unit a user plans a campaign with: t0 of flow
/// simulated per CPU-minute of a job (its simulated time t_end over its engine wall time,
/// summed over resumes; a job runs on one core unless it was given --threads T, when its
/// CPU time is T times the wall time), per model and dimension. `campaign status` and the
/// report show it (docs/cli.md); docs/database.md has the per-job query.
#include <cstdint>
#include <string>
#include <vector>

#include "orchestrator/campaign/campaign_scope.h"
#include "orchestrator/db/database.h"
#include "orchestrator/db/typed_columns.h"

namespace beverloo {

struct ModelSpeed {
  std::string model;  ///< "sp 2D", "dp_smooth 2D", ...
  int jobs = 0;
  double median = 0, min = 0, max = 0;  ///< t0 per CPU-minute over the finished jobs
};

/// Per model and dimension, over the jobs of the campaigns in scope (each once) with a stored result.
std::vector<ModelSpeed> campaign_speed(db::Database& db, const CampaignScope& scope);

/// The SQL of one job's value, over results r (the runs view's column of the same name).
using db::kT0PerCpuMinuteSql;

}  // namespace beverloo
