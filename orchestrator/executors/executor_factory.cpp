#include "executor_factory.h"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <utility>

#include "local_executor.h"
#include "slurm_executor.h"

namespace beverloo {
namespace {
using Make = std::function<std::unique_ptr<Executor>(CampaignStore&, const ExecutorSettings&)>;

const std::vector<std::pair<std::string, Make>>& registry() {
  static const std::vector<std::pair<std::string, Make>> r = {
      {"local",
       [](CampaignStore& store, const ExecutorSettings& s) -> std::unique_ptr<Executor> {
         return std::make_unique<LocalExecutor>(store, s.campaign_dir, s.workers, s.heartbeat_s);
       }},
      {"slurm",
       [](CampaignStore& store, const ExecutorSettings& s) -> std::unique_ptr<Executor> {
         // array tasks run elsewhere and in other working directories: an absolute path
         const std::string dir = std::filesystem::absolute(s.campaign_dir).lexically_normal().string();
         return std::make_unique<SlurmExecutor>(store, dir, s.slurm);
       }},
  };
  return r;
}
}  // namespace

std::vector<std::string> executor_names() {
  std::vector<std::string> names;
  for (const auto& [name, make] : registry()) names.push_back(name);
  return names;
}

std::unique_ptr<Executor> make_executor(const std::string& name, CampaignStore& store, const ExecutorSettings& s) {
  for (const auto& [n, make] : registry())
    if (n == name) return make(store, s);
  throw std::invalid_argument("unknown executor \"" + name + "\"");
}

}  // namespace beverloo
