#include "job_output.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/digest.h"
#include "h5.h"

namespace beverloo::job_output {
namespace fs = std::filesystem;

namespace {
std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw IoError("cannot read " + p.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

ResultCheck check_result(const std::string& dir, const SimConfig& c) {
  const fs::path result = fs::path(dir) / kResult, summary = fs::path(dir) / kSummary;
  std::error_code ec;
  if (!fs::exists(result, ec)) return {ResultState::None, ""};
  try {
    if (!fs::is_regular_file(result)) return {ResultState::Damaged, result.string() + " is not a regular file"};
    H5Handle f = h5::open_file(result.string());
    H5Handle p = h5::open_group(f, "parameters");
    if (h5::attr_string(p, "job_json") != c.to_json().dump())
      return {ResultState::OtherJob, result.string() + " holds the result of a different job"};
    H5Handle g = h5::open_group(f, "result");
    const double Q = h5::attr_double(g, "Q"), Q_err = h5::attr_double(g, "Q_err");
    if (!std::isfinite(Q) || !std::isfinite(Q_err))
      return {ResultState::Damaged, result.string() + ": Q or its error is not finite"};
    H5Handle run = h5::open_group(f, "run");
    if (!fs::is_regular_file(summary)) return {ResultState::Damaged, summary.string() + " is missing"};
    const nlohmann::json s = nlohmann::json::parse(read_text(summary));
    // the summary must say what result.h5 says (a summary edited after the engine wrote it, or
    // one left by another run, is not ingested)
    if (!s.is_object() || s.value("Q", double(NAN)) != Q || s.value("Q_err", double(NAN)) != Q_err ||
        s.value("steps", std::int64_t{-1}) != h5::attr_int64(run, "steps") ||
        s.value("seed", std::uint64_t{0}) != static_cast<std::uint64_t>(h5::attr_int64(p, "seed")))
      return {ResultState::Damaged, summary.string() + " disagrees with " + result.string()};
    H5Handle prof = h5::open_group(f, "profile");
    (void)h5::read_doubles(prof, "v_g");
  } catch (const std::exception& e) {
    return {ResultState::Damaged, std::string("unreadable result: ") + e.what()};
  }
  return {ResultState::Complete, ""};
}

std::map<std::string, std::string> result_digests(const std::string& dir) {
  std::map<std::string, std::string> d;
  for (const char* name : {kResult, kSummary}) d[name] = sha256_hex(read_text(fs::path(dir) / name));
  return d;
}

CompletedRun read_completed(const std::string& dir, const SimConfig& c, const std::map<std::string, std::string>& digests) {
  const ResultCheck check = check_result(dir, c);
  if (check.state != ResultState::Complete)
    throw IoError(check.state == ResultState::None ? dir + ": no " + kResult : check.reason);
  // the bytes the engine wrote, not bytes changed since (an edited summary, a copied result);
  // the summary's bytes read for the check are the ones handed on
  CompletedRun out;
  for (const char* name : {kResult, kSummary}) {
    const auto it = digests.find(name);
    if (it == digests.end()) throw IoError(dir + ": the outcome records no digest of " + name);
    std::string bytes = read_text(fs::path(dir) / name);
    if (it->second != sha256_hex(bytes))
      throw IoError((fs::path(dir) / name).string() + " changed after the engine wrote it (its SHA-256 is not the one recorded)");
    if (std::string_view(name) == kSummary) out.summary_json = std::move(bytes);
  }
  H5Handle f = h5::open_file((fs::path(dir) / kResult).string());
  H5Handle g = h5::open_group(f, "profile");
  out.h = h5::read_doubles(g, "h");
  out.v_g = h5::read_doubles(g, "v_g");
  out.v_g_err = h5::read_doubles(g, "v_g_err");
  return out;
}

DrainRecord read_drain(const std::string& dir) {
  const fs::path result = fs::path(dir) / kResult;
  if (!fs::is_regular_file(result)) throw IoError(dir + ": no " + kResult);
  DrainRecord d;
  try {
    H5Handle f = h5::open_file(result.string());
    H5Handle p = h5::open_group(f, "parameters");
    d.job_json = h5::attr_string(p, "job_json");
    const nlohmann::json job = nlohmann::json::parse(d.job_json);
    if (job.value("reinject", true))
      throw ConfigError(dir, "is not a draining hopper's result (its job has reinject = true)");
    d.w = job.at("w").get<double>();
    H5Handle g = h5::open_group(f, "drain");
    d.n_initial = static_cast<int>(h5::attr_int64(g, "n_initial"));
    H5Handle e = h5::open_group(f, "exits");
    d.exit_time = h5::read_doubles(e, "time");
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError(result.string() + ": unreadable: " + e.what());
  }
  return d;
}

void remove_result(const std::string& dir) {
  for (const char* name : {kResult, kSummary, kFailure}) {
    std::error_code ec;
    fs::remove(fs::path(dir) / name, ec);
  }
}

}  // namespace beverloo::job_output
