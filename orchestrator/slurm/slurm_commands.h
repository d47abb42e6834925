#pragma once
/// \file slurm_commands.h
/// \brief Runs Slurm's command-line tools (no shell: arguments go to exec as they are) and
/// counts every call, so that the coordinator's load on slurmctld can be reported.
#include <map>
#include <string>
#include <vector>

namespace beverloo::slurm {

struct CommandResult {
  int rc = -1;  ///< exit status; -1 if it could not run or timed out
  std::string out, err;
  std::string text() const { return out + err; }
};

class Commands {
 public:
  /// Runs argv[0] (looked up in PATH) with a time limit; it is killed when it runs over.
  CommandResult run(const std::vector<std::string>& argv, double timeout_s = 60);
  /// Calls per command name ("squeue", "sbatch", ...).
  const std::map<std::string, int>& calls() const { return calls_; }
  int total() const;

 private:
  std::map<std::string, int> calls_;
};

}  // namespace beverloo::slurm
