#pragma once
/// \file adaptive_planner.h
/// \brief The planner of adaptive sweeps (issue 30; the sweep's "adaptive" block,
/// orchestrator/sweep/adaptive_spec.h): per Beverloo series, when none of its jobs is pending
/// or running, it fits the series (the fit of `beverloo fit`) and either adds one job at the
/// width where a run reduces the variance of k and beta most per CPU (A-optimal per cost,
/// reports/next_width.h; a width the series has already takes the next replica), or stops the
/// series: its targets met, its budget of added jobs spent, or no fit possible (fewer than
/// three flowing widths above k, or a singular design). Deciding only on a quiet series makes
/// each decision a function of finished results alone: the same results give the same jobs,
/// whatever order workers finished in, and a campaign killed anywhere resumes to the same
/// decisions. An added job that equals an existing job (of any campaign) is that job.
#include "orchestrator/campaign/planner.h"

namespace beverloo {

class AdaptivePlanner final : public CampaignPlanner {
 public:
  std::vector<PlanDecision> plan(db::Database& db, std::int64_t campaign) override;
};

}  // namespace beverloo
