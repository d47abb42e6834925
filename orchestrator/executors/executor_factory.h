#pragma once
/// \file executor_factory.h
/// \brief The one place that knows which executors exist: the CLI offers their names, the
/// coordinator asks for one by name. A new executor is a class behind executor.h and a row here.
#include <memory>
#include <string>
#include <vector>

#include "executor.h"
#include "executor_options.h"

namespace beverloo {

/// What any executor may need to start; each takes its own part.
struct ExecutorSettings {
  std::string campaign_dir;
  int workers = 0;          ///< local: worker processes
  int threads = 1;          ///< threads per job (slurm: --cpus-per-task)
  double heartbeat_s = 30;  ///< local: heartbeat interval of live workers
  ExecutorOptionValues options;  ///< the executor's own command-line options, as given
};

/// The names `--executor` accepts, in the order the help lists them.
std::vector<std::string> executor_names();
/// Every executor's declared options, with the executor's name, in registry order.
struct DeclaredOption {
  std::string executor;
  ExecutorOption option;
};
std::vector<DeclaredOption> declared_executor_options();
/// Throws ConfigError naming the flag when an option of another executor was given (a Slurm
/// partition for a local run is a mistake, not something to ignore) or a value is not of its
/// option's kind and range. Call before writing anything.
void check_executor_options(const std::string& name, const ExecutorOptionValues& given);
/// Throws std::invalid_argument for an unknown name, ConfigError for a bad option value.
std::unique_ptr<Executor> make_executor(const std::string& name, CampaignStore& store, const ExecutorSettings& s);

}  // namespace beverloo
