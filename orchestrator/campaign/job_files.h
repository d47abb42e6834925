#pragma once
/// \file job_files.h
/// \brief The file protocol between coordinator and worker, in jobs/<dir>/ (the same for every
/// executor): spec.json (coordinator -> worker: key, attempt, token, job), lock (a flock that
/// the worker holds while it lives), heartbeat.json (worker -> coordinator, rewritten every
/// heartbeat_s while the attempt runs), the engine's files, and outcome.json (worker ->
/// coordinator, written last, atomically, carrying the attempt's token).
/// Slurm array tasks find their attempts in a manifest, slurm/<submission>/manifest.json:
/// {"root": campaign dir, "tasks": [[{"dir": "jobs/..", "token": ".."}, ...], ...]}, one list
/// per array index (several short jobs bundled into one task run one after the other).
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace beverloo::job_files {

inline constexpr const char* kSpec = "spec.json";
inline constexpr const char* kLock = "lock";
inline constexpr const char* kOutcome = "outcome.json";
inline constexpr const char* kLog = "log";
inline constexpr const char* kHeartbeat = "heartbeat.json";

struct Outcome {
  std::string token;
  int attempt_no = 0;
  int exit_code = 0;
  std::string failure_class, message;
  /// On success: the SHA-256 of each file of the engine's result (job_output::result_digests),
  /// taken as the engine finished, so that the coordinator ingests exactly those bytes.
  std::map<std::string, std::string> files;
};

/// What a live worker last said about itself.
struct Heartbeat {
  std::string token, host;
  double unix_time = 0;     ///< when it was written (the worker's clock)
  std::int64_t step = 0;    ///< the engine's step (0 before the flow starts)
  long pid = 0;
  std::string slurm_job;    ///< "<array>_<task>" under Slurm, else empty
  int slurm_restarts = -1;  ///< SLURM_RESTART_COUNT (-1: not under Slurm)
};

std::optional<Outcome> read_outcome(const std::string& job_dir);
void write_outcome(const std::string& job_dir, const Outcome& o);
std::optional<Heartbeat> read_heartbeat(const std::string& job_dir);
void write_heartbeat(const std::string& job_dir, const Heartbeat& h);
/// The whole file as text ("" if it cannot be read).
std::string read_text(const std::string& path);
/// True if some process holds the job's lock (a live worker).
bool lock_is_held(const std::string& job_dir);

}  // namespace beverloo::job_files
