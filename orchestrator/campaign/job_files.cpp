#include "job_files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"

namespace beverloo::job_files {

void write_spec(const std::string& job_dir, const Spec& s) {
  nlohmann::json j = {{"key", s.key},
                            {"attempt_no", s.attempt_no},
                            {"token", s.token},
                            {"heartbeat_s", s.heartbeat_s},
                            {"threads", s.threads},
                            {"job", s.job}};
  if (!s.continue_from.empty()) j["continue_from"] = s.continue_from;
  write_text_atomically((std::filesystem::path(job_dir) / kSpec).string(), j.dump(2) + "\n");
}

SpecRead read_spec(const std::string& path) {
  SpecRead r;
  nlohmann::json j;
  std::ifstream in(path);
  if (!in) {
    r.unreadable = true;
    r.problem = "cannot be read";
    return r;
  }
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception&) {
    r.unreadable = true;
    r.problem = "is not JSON";
    return r;
  }
  // a damaged spec is a message, not an abort: every field with its type before it is read
  auto problem = [&]() -> std::string {
    if (!j.is_object()) return "is not a JSON object";
    if (!j.contains("token") || !j["token"].is_string()) return "\"token\": missing or not a string";
    r.token = j["token"].get<std::string>();
    if (j.contains("key") && !j["key"].is_string()) return "\"key\": not a string";
    if (!j.contains("attempt_no") || !j["attempt_no"].is_number_integer()) return "\"attempt_no\": missing or not an integer";
    if (!j.contains("job") || !j["job"].is_object()) return "\"job\": missing or not an object";
    if (j.contains("heartbeat_s") && !(j["heartbeat_s"].is_number() && j["heartbeat_s"].get<double>() > 0))
      return "\"heartbeat_s\": not a positive number";
    if (j.contains("threads") && !(j["threads"].is_number_integer() && j["threads"].get<std::int64_t>() >= 1 &&
                                   j["threads"].get<std::int64_t>() <= 4096))
      return "\"threads\": not an integer from 1 to 4096";
    if (j.contains("continue_from")) {
      // only a sibling job's checkpoint: the coordinator writes nothing else here
      const std::filesystem::path p = j["continue_from"].is_string() ? j["continue_from"].get<std::string>() : "";
      auto it = p.begin();
      const bool sibling = std::distance(p.begin(), p.end()) == 3 && *it++ == ".." && it->string() != ".." &&
                           it->string() != "." && *++it == "checkpoint.h5";
      if (!sibling) return "\"continue_from\": not \"../<job directory>/checkpoint.h5\"";
    }
    return "";
  };
  r.problem = problem();
  if (!r.problem.empty()) return r;
  Spec s;
  s.key = j.value("key", "");
  s.attempt_no = j["attempt_no"].get<int>();
  s.token = r.token;
  s.heartbeat_s = j.value("heartbeat_s", 30.0);
  s.threads = static_cast<int>(j.value("threads", std::int64_t{1}));
  s.job = std::move(j["job"]);
  s.continue_from = j.value("continue_from", "");
  r.spec = std::move(s);
  return r;
}

std::optional<Outcome> read_outcome(const std::string& job_dir) {
  std::ifstream in(std::filesystem::path(job_dir) / kOutcome);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    Outcome o{j.at("token"), j.at("attempt_no"), j.at("exit_code"), j.value("failure_class", ""),
              j.value("message", ""), {}};
    if (j.contains("files")) o.files = j.at("files").get<std::map<std::string, std::string>>();
    return o;
  } catch (const std::exception&) {
    return std::nullopt;  // written atomically, so a broken one is foreign: ignore it
  }
}

void write_outcome(const std::string& job_dir, const Outcome& o) {
  const nlohmann::json j = {{"token", o.token},
                            {"attempt_no", o.attempt_no},
                            {"exit_code", o.exit_code},
                            {"failure_class", o.failure_class},
                            {"message", o.message},
                            {"files", o.files}};
  write_text_atomically((std::filesystem::path(job_dir) / kOutcome).string(), j.dump(2) + "\n");
}

std::optional<Heartbeat> read_heartbeat(const std::string& job_dir) {
  std::ifstream in(std::filesystem::path(job_dir) / kHeartbeat);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return Heartbeat{j.at("token"), j.value("host", ""), j.at("unix_time"), j.value("step", std::int64_t{0}),
                     j.value("pid", 0L), j.value("slurm_job", ""), j.value("slurm_restarts", -1)};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

void write_heartbeat(const std::string& job_dir, const Heartbeat& h) {
  const nlohmann::json j = {{"token", h.token},         {"host", h.host}, {"unix_time", h.unix_time},
                            {"step", h.step},           {"pid", h.pid},   {"slurm_job", h.slurm_job},
                            {"slurm_restarts", h.slurm_restarts}};
  write_text_atomically((std::filesystem::path(job_dir) / kHeartbeat).string(), j.dump() + "\n");
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool lock_is_held(const std::string& job_dir) {
  const std::string path = (std::filesystem::path(job_dir) / kLock).string();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
  ::close(fd);  // releases our probe lock if we got it
  return held;
}

}  // namespace beverloo::job_files
