// Executors declare their own command-line options (orchestrator/executors/executor_options.h):
// the Slurm executor's values land in its settings, bad values and another executor's options
// are refused with the flag named.
#include <gtest/gtest.h>

#include "core/errors.h"
#include "orchestrator/executors/executor_factory.h"
#include "orchestrator/executors/slurm_executor.h"

namespace beverloo {
namespace {

TEST(ExecutorOptions, SlurmValuesLandInItsSettings) {
  const ExecutorOptionValues given = {{"--partition", {"short"}},        {"--time-limit", {"1:00:00"}},
                                      {"--max-array", {"500"}},          {"--throttle", {"8"}},
                                      {"--bundle", {"3"}},               {"--bundle-target", {"900.5"}},
                                      {"--signal-lead", {"300"}},        {"--max-in-flight", {"77"}},
                                      {"--poll-min", {"0.5"}},           {"--poll-max", {"30"}},
                                      {"--result-grace", {"0"}},         {"--stall-timeout", {"1200"}},
                                      {"--sbatch-arg", {"--account=x", "--mem=2G"}},
                                      {"--worker-binary", {"/shared/beverloo"}}};
  const SlurmOptions o = SlurmExecutor::settings_from(given, 4);
  EXPECT_EQ(o.partition, "short");
  EXPECT_EQ(o.time_limit, "1:00:00");
  EXPECT_EQ(o.max_array, 500);
  EXPECT_EQ(o.throttle, 8);
  EXPECT_EQ(o.bundle, 3);
  EXPECT_EQ(o.bundle_target_s, 900.5);
  EXPECT_EQ(o.signal_lead_s, 300);
  EXPECT_EQ(o.max_in_flight, 77);
  EXPECT_EQ(o.poll_min_s, 0.5);
  EXPECT_EQ(o.poll_max_s, 30);
  EXPECT_EQ(o.result_grace_s, 0);
  EXPECT_EQ(o.stall_timeout_s, 1200);
  EXPECT_EQ(o.sbatch_args, (std::vector<std::string>{"--account=x", "--mem=2G"}));
  EXPECT_EQ(o.worker_binary, "/shared/beverloo");
  EXPECT_EQ(o.cpus_per_task, 4);
  // every declared option was given above: a row whose value goes nowhere would show here
  EXPECT_EQ(SlurmExecutor::options().size(), given.size());
  // nothing given: the defaults of SlurmOptions
  const SlurmOptions d = SlurmExecutor::settings_from({}, 1);
  EXPECT_EQ(d.bundle_target_s, SlurmOptions{}.bundle_target_s);
  EXPECT_EQ(d.max_in_flight, SlurmOptions{}.max_in_flight);
}

TEST(ExecutorOptions, BadValuesAreRefusedWithTheFlagNamed) {
  for (const auto& [flag, value] : std::vector<std::pair<std::string, std::string>>{
           {"--max-array", "0"}, {"--bundle", "2.5"}, {"--poll-min", "0"}, {"--poll-min", "abc"}, {"--poll-max", "inf"},
           {"--result-grace", "-1"}, {"--signal-lead", "5"}, {"--throttle", ""}, {"--bundle-target", "1e999"}}) {
    try {
      SlurmExecutor::settings_from({{flag, {value}}}, 1);
      ADD_FAILURE() << flag << " " << value << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.field(), flag) << e.what();
    }
  }
}

TEST(ExecutorOptions, AnotherExecutorsOptionIsRefused) {
  EXPECT_NO_THROW(check_executor_options("slurm", {{"--partition", {"short"}}}));
  EXPECT_NO_THROW(check_executor_options("local", {}));
  try {
    check_executor_options("local", {{"--partition", {"short"}}});
    ADD_FAILURE() << "a Slurm option on a local run was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "--partition");
    EXPECT_NE(std::string(e.what()).find("slurm executor"), std::string::npos) << e.what();
  }
  // its own options' values are checked too, before anything is written
  try {
    check_executor_options("slurm", {{"--bundle", {"0"}}});
    ADD_FAILURE() << "--bundle 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "--bundle");
  }
  // the factory lists every declared option with its executor, flags unique per executor
  std::set<std::pair<std::string, std::string>> seen;
  for (const DeclaredOption& d : declared_executor_options())
    EXPECT_TRUE(seen.insert({d.executor, d.option.flag}).second) << d.option.flag;
  EXPECT_FALSE(seen.empty());
}

}  // namespace
}  // namespace beverloo
