// The Slurm executor's command-line options: one row each (the flag, its help, kind and range,
// and where its value goes in SlurmOptions). The CLI adds them from SlurmExecutor::options().
#include <functional>

#include "slurm_executor.h"

namespace beverloo {
namespace {

using K = ExecutorOption::Kind;
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

struct SlurmOptionRow {
  ExecutorOption option;
  std::function<void(SlurmOptions&, const std::vector<std::string>& values, double number)> set;
};

const std::vector<SlurmOptionRow>& rows() {
  static const std::vector<SlurmOptionRow> r = {
      {{"--partition", "slurm: partition (default: the cluster's default)", K::Text},
       [](SlurmOptions& o, const auto& v, double) { o.partition = v.back(); }},
      {{"--time-limit", "slurm: --time per array task, e.g. 4:00:00 (default: the partition's)", K::Text},
       [](SlurmOptions& o, const auto& v, double) { o.time_limit = v.back(); }},
      {{"--max-array", "slurm: tasks per array (default: MaxArraySize - 1, at most 1000)", K::Integer, 1, 1e6},
       [](SlurmOptions& o, const auto&, double n) { o.max_array = static_cast<int>(n); }},
      {{"--throttle", "slurm: array tasks running at once per array, the %N of --array (default: no limit)", K::Integer, 1,
        1e6},
       [](SlurmOptions& o, const auto&, double n) { o.throttle = static_cast<int>(n); }},
      {{"--bundle", "slurm: jobs per array task (default: packed by estimated cost, see --bundle-target)", K::Integer, 1,
        1e4},
       [](SlurmOptions& o, const auto&, double n) { o.bundle = static_cast<int>(n); }},
      {{"--bundle-target", "slurm: estimated seconds of work per array task when packing (default 600)", K::Real, 0, kNone,
        true},
       [](SlurmOptions& o, const auto&, double n) { o.bundle_target_s = n; }},
      {{"--signal-lead", "slurm: seconds before the time limit at which workers checkpoint (default 120)", K::Integer, 10,
        86400},
       [](SlurmOptions& o, const auto&, double n) { o.signal_lead_s = static_cast<int>(n); }},
      {{"--max-in-flight", "slurm: attempts submitted and not yet ended (default 10000)", K::Integer, 1, 1e7},
       [](SlurmOptions& o, const auto&, double n) { o.max_in_flight = static_cast<int>(n); }},
      {{"--poll-min", "slurm: seconds between squeue calls after a change (default 2)", K::Real, 0, kNone, true},
       [](SlurmOptions& o, const auto&, double n) { o.poll_min_s = n; }},
      {{"--poll-max", "slurm: the interval doubles while nothing changes, up to this (default 60)", K::Real, 0, kNone, true},
       [](SlurmOptions& o, const auto&, double n) { o.poll_max_s = n; }},
      {{"--result-grace", "slurm: seconds to wait for the files of a task that ended (default 30)", K::Real, 0, kNone},
       [](SlurmOptions& o, const auto&, double n) { o.result_grace_s = n; }},
      {{"--stall-timeout", "slurm: a RUNNING task silent this long is cancelled and rerun (default 600)", K::Real, 0, kNone,
        true},
       [](SlurmOptions& o, const auto&, double n) { o.stall_timeout_s = n; }},
      {{"--sbatch-arg", "slurm: passed to sbatch as it is (repeat: --sbatch-arg=--account=X --sbatch-arg=--mem=2G)",
        K::TextList},
       [](SlurmOptions& o, const auto& v, double) { o.sbatch_args = v; }},
      {{"--worker-binary", "slurm: the beverloo compute nodes run (default: this one)", K::Text},
       [](SlurmOptions& o, const auto& v, double) { o.worker_binary = v.back(); }},
  };
  return r;
}

}  // namespace

std::vector<ExecutorOption> SlurmExecutor::options() {
  std::vector<ExecutorOption> out;
  for (const SlurmOptionRow& row : rows()) out.push_back(row.option);
  return out;
}

SlurmOptions SlurmExecutor::settings_from(const ExecutorOptionValues& given, int threads) {
  SlurmOptions o;
  o.cpus_per_task = threads;
  for (const SlurmOptionRow& row : rows()) {
    const auto it = given.find(row.option.flag);
    if (it == given.end() || it->second.empty()) continue;
    const bool numeric = row.option.kind == K::Integer || row.option.kind == K::Real;
    row.set(o, it->second, numeric ? option_number(row.option, it->second.back()) : 0.0);
  }
  return o;
}

}  // namespace beverloo
