#include "executor_factory.h"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <utility>

#include "core/errors.h"
#include "local_executor.h"
#include "slurm_executor.h"

namespace beverloo {
namespace {
using Make = std::function<std::unique_ptr<Executor>(CampaignStore&, const ExecutorSettings&)>;

struct Row {
  std::string name;
  std::vector<ExecutorOption> options;  ///< its own command-line options (none: local)
  Make make;
};

const std::vector<Row>& registry() {
  static const std::vector<Row> r = {
      {"local", {},
       [](CampaignStore& store, const ExecutorSettings& s) -> std::unique_ptr<Executor> {
         return std::make_unique<LocalExecutor>(store, s.campaign_dir, s.workers, s.heartbeat_s);
       }},
      {"slurm", SlurmExecutor::options(),
       [](CampaignStore& store, const ExecutorSettings& s) -> std::unique_ptr<Executor> {
         // array tasks run elsewhere and in other working directories: an absolute path
         const std::string dir = std::filesystem::absolute(s.campaign_dir).lexically_normal().string();
         return std::make_unique<SlurmExecutor>(store, dir, SlurmExecutor::settings_from(s.options, s.threads));
       }},
  };
  return r;
}
}  // namespace

std::vector<std::string> executor_names() {
  std::vector<std::string> names;
  for (const Row& row : registry()) names.push_back(row.name);
  return names;
}

std::vector<DeclaredOption> declared_executor_options() {
  std::vector<DeclaredOption> out;
  for (const Row& row : registry())
    for (const ExecutorOption& o : row.options) out.push_back({row.name, o});
  return out;
}

void check_executor_options(const std::string& name, const ExecutorOptionValues& given) {
  for (const auto& [flag, values] : given) {
    if (values.empty()) continue;
    const ExecutorOption* ours = nullptr;  // the chosen executor's row of this flag
    std::string other;                     // else the first executor that declares it
    for (const Row& row : registry())
      for (const ExecutorOption& o : row.options)
        if (o.flag == flag) {
          if (row.name == name) ours = &o;
          else if (other.empty()) other = row.name;
        }
    if (!ours) {
      if (!other.empty())
        throw ConfigError(flag, "is an option of the " + other + " executor; this run's --executor is " + name);
      continue;
    }
    if (ours->kind == ExecutorOption::Kind::Integer || ours->kind == ExecutorOption::Kind::Real)
      for (const std::string& v : values) option_number(*ours, v);  // by kind and range
  }
}

std::unique_ptr<Executor> make_executor(const std::string& name, CampaignStore& store, const ExecutorSettings& s) {
  for (const Row& row : registry())
    if (row.name == name) {
      check_executor_options(name, s.options);
      return row.make(store, s);
    }
  throw std::invalid_argument("unknown executor \"" + name + "\"");
}

}  // namespace beverloo
