#pragma once
/// \file coordinator.h
/// \brief The coordinator: the only process that writes the campaign database. It holds the
/// campaign lock, reconciles attempts left by an earlier coordinator, claims pending jobs,
/// starts workers through an executor, ingests their results and classifies their failures.
#include <atomic>
#include <optional>
#include <string>

#include "campaign_dir.h"
#include "planner.h"
#include "engine/protocol/run_hopper.h"
#include "orchestrator/executors/executor_options.h"

namespace beverloo {

struct CampaignOptions {
  std::string dir = "campaign";
  int workers = 0;           ///< 0: the number of cores over threads
  int threads = 1;           ///< threads per job (results do not depend on it); local: workers x threads <= cores
  int max_retries = 2;       ///< science retries per job (blow-up, I/O); infrastructure ones are free
  int max_infra_retries = 50;  ///< guard against endless kill loops
  double job_timeout_s = 0;  ///< wall seconds per attempt (0: none); then SIGTERM, checkpoint, resume later
  double heartbeat_s = 30;   ///< how often attempts.heartbeat_at is refreshed for live workers
  ProgressMode progress = ProgressMode::Auto;
  std::string executor = "local";      ///< a name of executor_factory's registry: local | slurm
  ExecutorOptionValues executor_options;  ///< the executor's own options as given (it parses them)
  /// Grows the campaign as results arrive (an adaptive sweep); nullptr: a fixed grid.
  CampaignPlanner* planner = nullptr;
};

/// `beverloo run`: creates or reopens the campaign of sweep_path (if given) and runs every job
/// that is not done. Returns an exit code.
int run_campaign(const std::optional<std::string>& sweep_path, const CampaignOptions& o);

}  // namespace beverloo
