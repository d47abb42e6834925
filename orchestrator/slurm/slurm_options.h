#pragma once
/// \file slurm_options.h
/// \brief Settings of the Slurm executor (`beverloo run --executor slurm ...`).
#include <string>
#include <vector>

namespace beverloo {

struct SlurmOptions {
  std::string partition;           ///< --partition (empty: the cluster's default)
  std::string time_limit;          ///< --time per array task, Slurm's format (empty: the partition's default)
  int max_array = 0;               ///< tasks per array (0: the cluster's MaxArraySize - 1, at most 1000)
  int throttle = 0;                ///< %N: array tasks running at once per array (0: no limit)
  int bundle = 0;                  ///< jobs per array task (0: pack jobs by their estimated cost)
  double bundle_target_s = 600;    ///< auto bundling: estimated seconds of work per array task
  int signal_lead_s = 120;         ///< --signal=B:USR1@lead: checkpoint this long before the time limit
  int max_in_flight = 10000;       ///< attempts submitted and not yet ended
  int cpus_per_task = 1;           ///< --cpus-per-task: the threads of each job (run --threads)
  double poll_min_s = 2;           ///< squeue polling interval after a change ...
  double poll_max_s = 60;          ///< ... doubling while nothing changes, up to this
  double result_grace_s = 30;      ///< a task that ended without a result file: wait this long (NFS lag)
  double stall_timeout_s = 600;    ///< a RUNNING task whose heartbeat is older than this is cancelled and rerun
  std::vector<std::string> sbatch_args;  ///< passed to sbatch as they are (--account, --qos, --mem, ...)
  std::string worker_binary;       ///< the beverloo that compute nodes run (default: this one; must be on the shared file system)
};

}  // namespace beverloo
