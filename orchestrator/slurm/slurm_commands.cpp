#include "slurm_commands.h"

#include "core/child_process.h"

namespace beverloo::slurm {

int Commands::total() const {
  int n = 0;
  for (const auto& [name, count] : calls_) n += count;
  return n;
}

CommandResult Commands::run(const std::vector<std::string>& argv, double timeout_s) {
  ++calls_[argv.at(0)];
  ChildResult c = run_child(argv, timeout_s);
  return CommandResult{c.rc, std::move(c.out), std::move(c.err)};
}

}  // namespace beverloo::slurm
