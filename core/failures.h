#pragma once
/// \file failures.h
/// \brief Every way a command or a job attempt can end, in one table: its exit code, its
/// failure class (the string stored in attempts.failure_class), the state the attempt row gets,
/// and the retry policy. The worker, the coordinator, the Slurm reconciliation and the store all
/// read this table; docs/cli.md and docs/database.md describe it.
#include <optional>
#include <string_view>

namespace beverloo {

/// The exit codes of every beverloo command (docs/cli.md).
namespace exit_code {
inline constexpr int kOk = 0;           ///< finished (a clogged run is a finished run)
inline constexpr int kInternal = 1;     ///< a bug: unexpected exception
inline constexpr int kConfig = 2;       ///< bad input: names the field and the reason; nothing written
inline constexpr int kUnstable = 3;     ///< the simulation became unphysical (NaN, escape, overlap)
inline constexpr int kIo = 4;           ///< reading or writing files failed
inline constexpr int kInterrupted = 5;  ///< stopped by SIGINT/SIGTERM/SIGUSR1 after writing a checkpoint
inline constexpr int kBusy = 6;         ///< another coordinator holds the campaign
inline constexpr int kJobsFailed = 7;   ///< the campaign finished, but some jobs failed for good
inline constexpr int kOutOfMemory = 8;  ///< an allocation failed (the machine's memory or the process's limit)
inline constexpr int kLockBusy = 75;    ///< a worker found its job locked by another live worker
}  // namespace exit_code

enum class FailureClass {
  InvalidParameters, BlowUp, Killed, Timeout, Io, Interrupted, Lost, Internal,
  DiskFull,  ///< an I/O failure for want of room (disk_space.h): the coordinator stops
  // what Slurm can end an attempt with (slurm_output.h has the Slurm state table)
  Cancelled, Preempted, NodeFailure, OutOfMemory, Stalled
};

/// What happens to the job after an attempt ends this way.
enum class RetryPolicy {
  Never,     ///< the job fails at once (its parameters are wrong, or a retry would repeat it bit for bit)
  Budgeted,  ///< pending again while the job's retry budget lasts (science failures)
  Free,      ///< pending again, resumed from its checkpoint, budget untouched (infrastructure)
  Cancel,    ///< the job is cancelled (a user cancelled it in the scheduler)
};

struct FailureInfo {
  FailureClass cls;
  std::string_view name;           ///< attempts.failure_class
  int exit_code;                   ///< what a worker exits with for it (-1: not a worker's exit)
  std::string_view attempt_state;  ///< attempts.state after it
  RetryPolicy retry;
};

const FailureInfo& failure_info(FailureClass c);
inline std::string_view to_string(FailureClass c) { return failure_info(c).name; }
/// Infrastructure failures resume from the checkpoint without using up the job's retry budget.
inline bool is_infrastructure(FailureClass c) { return failure_info(c).retry == RetryPolicy::Free; }
/// The class of a stored failure_class string (nullopt: unknown).
std::optional<FailureClass> failure_from_name(std::string_view name);
/// The class of a worker process's exit code (signals: Killed; unknown codes: Internal).
FailureClass failure_from_exit(bool signaled, int code);

}  // namespace beverloo
