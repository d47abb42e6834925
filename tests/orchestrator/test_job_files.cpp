// spec.json, the coordinator's word to a worker: one writer and one reader (job_files), so what
// is written is what is read, and a damaged file is a problem named by its field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "orchestrator/campaign/job_files.h"

namespace beverloo {
namespace {
namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() : path(fs::temp_directory_path() / ("beverloo-jobfiles-" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

TEST(JobFiles, SpecWrittenIsSpecRead) {
  TempDir d;
  const job_files::Spec out{"abc123", 3, "tok", 12.5, 2, nlohmann::json{{"w", 4.5}, {"model", "dp_smooth"}}, ""};
  job_files::write_spec(d.path.string(), out);
  const job_files::SpecRead r = job_files::read_spec((d.path / job_files::kSpec).string());
  ASSERT_TRUE(r.spec) << r.problem;
  EXPECT_EQ(r.spec->key, out.key);
  EXPECT_EQ(r.spec->attempt_no, 3);
  EXPECT_EQ(r.spec->token, "tok");
  EXPECT_EQ(r.spec->heartbeat_s, 12.5);
  EXPECT_EQ(r.spec->threads, 2);
  EXPECT_EQ(r.spec->job, out.job);
  EXPECT_EQ(r.spec->continue_from, "");
  EXPECT_FALSE(fs::exists(d.path / (std::string(job_files::kSpec) + ".tmp"))) << "written through a temporary name";
  job_files::Spec more = out;
  more.continue_from = "../0123456789abcdef/checkpoint.h5";
  job_files::write_spec(d.path.string(), more);
  const job_files::SpecRead m = job_files::read_spec((d.path / job_files::kSpec).string());
  ASSERT_TRUE(m.spec) << m.problem;
  EXPECT_EQ(m.spec->continue_from, more.continue_from);
}

TEST(JobFiles, DamagedSpecNamesItsFieldAndKeepsItsToken) {
  TempDir d;
  const std::string path = (d.path / job_files::kSpec).string();
  auto read = [&](const std::string& text) {
    std::ofstream(path) << text;
    return job_files::read_spec(path);
  };
  struct Case {
    const char* text;
    const char* field;
    const char* token;
  };
  for (const Case& c : {Case{R"({"attempt_no": 1, "job": {}})", "\"token\"", ""},
                        Case{R"({"token": "t", "attempt_no": "one", "job": {}})", "\"attempt_no\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": [1]})", "\"job\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "heartbeat_s": 0})", "\"heartbeat_s\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "threads": 4097})", "\"threads\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "key": 7})", "\"key\"", "t"},
                        // only a sibling job's checkpoint may be continued: nothing else on the disk
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "continue_from": "/etc/passwd"})", "\"continue_from\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "continue_from": "../../x/checkpoint.h5"})", "\"continue_from\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "continue_from": "../../checkpoint.h5"})", "\"continue_from\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "continue_from": "../a/result.h5"})", "\"continue_from\"", "t"},
                        Case{R"({"token": "t", "attempt_no": 1, "job": {}, "continue_from": 3})", "\"continue_from\"", "t"},
                        Case{R"([1, 2])", "JSON object", ""}}) {
    const job_files::SpecRead r = read(c.text);
    EXPECT_FALSE(r.spec) << c.text;
    EXPECT_FALSE(r.unreadable) << c.text;
    EXPECT_NE(r.problem.find(c.field), std::string::npos) << c.text << ": " << r.problem;
    EXPECT_EQ(r.token, c.token) << c.text;
  }
  const job_files::SpecRead defaults = read(R"({"token": "t", "attempt_no": 1, "job": {"w": 3}})");
  ASSERT_TRUE(defaults.spec) << defaults.problem;
  EXPECT_EQ(defaults.spec->threads, 1);
  EXPECT_EQ(defaults.spec->heartbeat_s, 30.0);
  EXPECT_TRUE(read("{\"token\": ").unreadable) << "not JSON";
  fs::remove(path);
  EXPECT_TRUE(job_files::read_spec(path).unreadable) << "no file";
}

}  // namespace
}  // namespace beverloo
