#pragma once
/// \file planner.h
/// \brief The seam through which a campaign grows while it runs (adaptive sweeps, issue 30).
/// The coordinator asks its planner after every round of finished jobs; what the planner
/// decides is stored with the jobs it adds in one transaction (CampaignStore::record_decisions).
/// The planner itself lives above the orchestrator (reports/adaptive_planner.h: it fits), so
/// the coordinator sees only this interface.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/db/database.h"
#include "orchestrator/sweep/sweep.h"

namespace beverloo {

struct PlanDecision {
  std::string series_key;
  std::string action;             ///< "add" or "stop"
  std::optional<JobSpec> job;     ///< the job to add ("add")
  std::string reason;             ///< why, in one sentence (shown by campaign status and the report)
  std::optional<double> k_err, beta_err, k_err_after, beta_err_after;
  int flowing_points = 0;
};

class CampaignPlanner {
 public:
  virtual ~CampaignPlanner() = default;
  /// The decisions due now for the campaign, from its database alone (the same database gives
  /// the same decisions: a resumed campaign repeats none and skips none).
  virtual std::vector<PlanDecision> plan(db::Database& db, std::int64_t campaign) = 0;
};

}  // namespace beverloo
