#pragma once
/// \file job_files.h
/// \brief The file protocol between coordinator and worker, in jobs/<dir>/ (the same for every
/// executor): spec.json (coordinator -> worker: key, attempt, token, job), lock (a flock that
/// the worker holds while it lives), the engine's files, and outcome.json (worker ->
/// coordinator, written last, atomically, carrying the attempt's token).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace beverloo::job_files {

inline constexpr const char* kSpec = "spec.json";
inline constexpr const char* kLock = "lock";
inline constexpr const char* kOutcome = "outcome.json";
inline constexpr const char* kLog = "log";
inline constexpr int kLockBusyExit = 75;  ///< a worker found its job locked by another live worker

struct Outcome {
  std::string token;
  int attempt_no = 0;
  int exit_code = 0;
  std::string failure_class, message;
};

std::optional<Outcome> read_outcome(const std::string& job_dir);
void write_outcome(const std::string& job_dir, const Outcome& o);
/// True if some process holds the job's lock (a live worker).
bool lock_is_held(const std::string& job_dir);

}  // namespace beverloo::job_files
