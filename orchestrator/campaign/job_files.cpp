#include "job_files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "engine/io/h5.h"

namespace beverloo::job_files {

std::optional<Outcome> read_outcome(const std::string& job_dir) {
  std::ifstream in(std::filesystem::path(job_dir) / kOutcome);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return Outcome{j.at("token"), j.at("attempt_no"), j.at("exit_code"), j.value("failure_class", ""),
                   j.value("message", "")};
  } catch (const std::exception&) {
    return std::nullopt;  // written atomically, so a broken one is foreign: ignore it
  }
}

void write_outcome(const std::string& job_dir, const Outcome& o) {
  const nlohmann::json j = {{"token", o.token},
                            {"attempt_no", o.attempt_no},
                            {"exit_code", o.exit_code},
                            {"failure_class", o.failure_class},
                            {"message", o.message}};
  write_text_atomically((std::filesystem::path(job_dir) / kOutcome).string(), j.dump(2) + "\n");
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
