// The engine's one answer to "is this job directory's result complete and intact?"
// (engine/io/job_output): the worker, `simulate --resume` and the coordinator's ingestion ask it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/io/job_output.h"
#include "engine/protocol/hopper_run.h"
#include "support.h"

namespace beverloo {
namespace {
namespace fs = std::filesystem;
using job_output::ResultState;

SimConfig tiny() {
  SimConfig c = testing::small_config(2, 60, 4.0, 0.3, 0.0);
  c.run.t_max = 3;
  c.run.min_transient = 1;
  c.run.min_window = 2;
  c.run.rate_bin = 0.25;
  c.run.checkpoint_interval = 0;
  c.resolve_and_validate();
  return c;
}

TEST(JobOutput, CompleteDamagedAndForeignResultsAreTold) {
  const fs::path dir = fs::temp_directory_path() / ("beverloo-job-output-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const SimConfig c = tiny();
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::None);
  RunOptions opt;
  opt.output_dir = dir.string();
  opt.progress = ProgressMode::Quiet;
  (void)run_hopper(c, opt);
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Complete);
  const auto digests = job_output::result_digests(dir.string());
  const auto run = job_output::read_completed(dir.string(), c, digests);
  EXPECT_FALSE(run.v_g.empty());
  // without the engine's digests, or with others, nothing is read
  EXPECT_THROW((void)job_output::read_completed(dir.string(), c, {}), IoError);
  auto wrong = digests;
  wrong[job_output::kSummary] = std::string(64, '0');
  EXPECT_THROW((void)job_output::read_completed(dir.string(), c, wrong), IoError);

  SimConfig other = c;
  other.w = 4.5;
  other.resolve_and_validate();
  EXPECT_EQ(job_output::check_result(dir.string(), other).state, ResultState::OtherJob);

  // a summary edited after the engine wrote it
  const fs::path summary = dir / job_output::kSummary;
  std::ifstream in(summary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  auto edited = nlohmann::json::parse(text);
  edited["Q"] = edited["Q"].get<double>() * 2 + 1;
  std::ofstream(summary) << edited.dump(2);
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Damaged);
  EXPECT_THROW((void)job_output::read_completed(dir.string(), c, digests), IoError);
  // an edit that keeps Q, its error, the steps and the seed passes the consistency check, not the digest
  auto subtle = nlohmann::json::parse(text);
  subtle["rho_n"] = subtle["rho_n"].get<double>() + 1;
  std::ofstream(summary) << subtle.dump(2);
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Complete);
  try {
    (void)job_output::read_completed(dir.string(), c, digests);
    ADD_FAILURE() << "an edited summary was read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("changed after the engine wrote it"), std::string::npos) << e.what();
  }
  // a missing summary, then a truncated result.h5
  std::ofstream(summary) << text;
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Complete);
  fs::remove(summary);
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Damaged);
  std::ofstream(summary) << text;
  fs::resize_file(dir / job_output::kResult, fs::file_size(dir / job_output::kResult) / 2);
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::Damaged);
  job_output::remove_result(dir.string());
  EXPECT_EQ(job_output::check_result(dir.string(), c).state, ResultState::None);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace beverloo
