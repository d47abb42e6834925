#pragma once
/// \file executor.h
/// \brief How workers are started and watched: the one seam between the coordinator and the
/// machine. Every executor uses the same job files (job_files.h: spec, lock, heartbeat,
/// outcome); the local one forks worker processes, the Slurm one submits job arrays. What an
/// attempt produced is always decided from its files by the coordinator; an executor only says
/// that an attempt has ended and what it knows about how.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/campaign/store.h"

namespace beverloo {

struct WorkerExit {
  std::int64_t attempt_id = 0;
  /// The worker process's own status, when the executor saw it (local children).
  bool have_status = false;
  bool signaled = false;
  int code = 0;  ///< exit code, or the signal number if signaled
  /// The scheduler's account of the end (Slurm), used when the files do not say more.
  std::optional<FailureClass> verdict;
  std::string message;
};

class Executor {
 public:
  virtual ~Executor() = default;
  virtual std::string name() const = 0;
  /// What stop_all() does to running work, for the coordinator's message when it stops.
  virtual std::string on_stop() const = 0;
  /// How many more attempts may be started now.
  virtual int free_slots() const = 0;
  /// Attempts started or adopted and not yet reported ended.
  virtual int in_flight() const = 0;
  /// Starts workers for claimed jobs whose spec.json is written.
  virtual void start(const std::vector<ClaimedJob>& jobs) = 0;
  /// After a coordinator restart: watch an attempt that an earlier coordinator started. Returns
  /// false if it certainly is not running any more (the coordinator then settles it from files).
  virtual bool adopt(const RunningAttempt& a) = 0;
  /// Attempts that ended since the last call.
  virtual std::vector<WorkerExit> poll() = 0;
  /// Sleeps until something may have happened (at most a fraction of a second).
  virtual void wait() = 0;
  /// The coordinator is stopping: local workers checkpoint and stop (their exits are returned);
  /// Slurm tasks keep running, to be collected by the next coordinator.
  virtual std::vector<WorkerExit> stop_all() = 0;
  /// Asks one worker to checkpoint and stop (--job-timeout); executors whose scheduler enforces
  /// time limits itself ignore it.
  virtual void stop(std::int64_t attempt_id) = 0;
};

}  // namespace beverloo
