#pragma once
/// \file job_files.h
/// \brief The file protocol between coordinator and worker, in jobs/<dir>/ (the same for every
/// executor): spec.json (coordinator -> worker: Spec, one writer and one reader here), lock (a flock that
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

/// spec.json: one attempt of one job, as the coordinator writes it for the worker.
struct Spec {
  std::string key;           ///< the job's content address
  int attempt_no = 0;
  std::string token;         ///< this attempt's (outcome.json and heartbeats carry it back)
  double heartbeat_s = 30;   ///< seconds between heartbeat records (> 0)
  int threads = 1;           ///< threads for the engine's steps, 1 .. 4096
  nlohmann::json job;        ///< the job file (an object; SimConfig::from_json reads it)
  /// Another job's checkpoint this one may continue when it has none of its own (the same
  /// trajectory, stopped earlier: RunOptions::continue_from), relative to this job's directory
  /// ("../<dir>/checkpoint.h5"); empty: none.
  std::string continue_from;
};
/// What read_spec() found: the spec, or why there is none. A spec.json that is there but damaged
/// has its problem (the field and what is wrong with it) and, where it has one, its token, so a
/// worker can tell a damaged spec of its own attempt from one of a newer attempt.
struct SpecRead {
  std::optional<Spec> spec;
  bool unreadable = false;  ///< no file, or not JSON
  std::string token;        ///< the token if the file has one as text (also when damaged)
  std::string problem;      ///< empty when spec is set
};
void write_spec(const std::string& job_dir, const Spec& s);
/// Reads and checks spec.json at path: every field the worker reads, with its type and range.
SpecRead read_spec(const std::string& path);

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
