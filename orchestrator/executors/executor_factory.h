#pragma once
/// \file executor_factory.h
/// \brief The one place that knows which executors exist: the CLI offers their names, the
/// coordinator asks for one by name. A new executor is a class behind executor.h and a row here.
#include <memory>
#include <string>
#include <vector>

#include "executor.h"
#include "orchestrator/slurm/slurm_options.h"

namespace beverloo {

/// What any executor may need to start; each takes its own part.
struct ExecutorSettings {
  std::string campaign_dir;
  int workers = 0;          ///< local: worker processes
  double heartbeat_s = 30;  ///< local: heartbeat interval of live workers
  SlurmOptions slurm;       ///< slurm: partition, limits, arrays
};

/// The names `--executor` accepts, in the order the help lists them.
std::vector<std::string> executor_names();
/// Throws std::invalid_argument for an unknown name.
std::unique_ptr<Executor> make_executor(const std::string& name, CampaignStore& store, const ExecutorSettings& s);

}  // namespace beverloo
