#pragma once
/// \file job_output.h
/// \brief The engine's files in a job directory, and the one answer to "does this directory
/// hold a complete, intact result of this job?". Only the engine reads or writes these files
/// (layout: docs/hdf5-layout.md); the worker, `simulate` and the coordinator ask here.
#include <map>
#include <string>
#include <vector>

#include "../config.h"

namespace beverloo::job_output {

inline constexpr const char* kResult = "result.h5";
inline constexpr const char* kSummary = "summary.json";
inline constexpr const char* kCheckpoint = "checkpoint.h5";
inline constexpr const char* kTrajectory = "trajectory.h5";
inline constexpr const char* kFailure = "failure.json";

enum class ResultState {
  None,      ///< no result.h5
  Complete,  ///< result.h5 and summary.json of this very job, readable and agreeing
  OtherJob,  ///< a readable result of a different canonical job
  Damaged,   ///< present but unreadable, truncated, without its summary, or disagreeing with it
};

struct ResultCheck {
  ResultState state = ResultState::None;
  std::string reason;  ///< for Damaged and OtherJob: what is wrong
};

/// Checks dir's result against the job c (canonical job JSON, Q and its error finite, the
/// summary's Q, Q_err, steps and seed equal to the result's). Never throws.
ResultCheck check_result(const std::string& dir, const SimConfig& c);

/// What a finished job gives the campaign store.
struct CompletedRun {
  std::string summary_json;  ///< summary.json as the engine wrote it
  std::vector<double> h, v_g, v_g_err;  ///< the velocity profile
};
/// SHA-256 of each of the result's files (result.h5, summary.json) as they are now; throws
/// IoError if one cannot be read. The worker records them in its outcome when the engine ends.
std::map<std::string, std::string> result_digests(const std::string& dir);

/// Reads a Complete result whose files still have the given digests (those the engine's
/// outcome recorded); throws IoError naming what is damaged, missing or changed otherwise.
CompletedRun read_completed(const std::string& dir, const SimConfig& c, const std::map<std::string, std::string>& digests);

/// A finished draining run's exits (reinject = false), for `beverloo experiment export-drain`.
struct DrainRecord {
  std::string job_json;           ///< the canonical job
  double w = 0;                   ///< orifice width, sigma_avg
  int n_initial = 0;
  std::vector<double> exit_time;  ///< t0, sorted
};
/// Reads dir's result; throws IoError if it is missing or damaged, ConfigError if the run was
/// not a draining hopper.
DrainRecord read_drain(const std::string& dir);

/// Removes the engine's result files (not the checkpoint): a damaged result is run again.
void remove_result(const std::string& dir);

}  // namespace beverloo::job_output
