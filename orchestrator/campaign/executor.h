#pragma once
/// \file executor.h
/// \brief How workers are started and watched: the one seam between the coordinator and the
/// machine. Every executor uses the same job files (job_files.h); the local one forks worker
/// processes, a Slurm one would submit array tasks.
#include <cstdint>
#include <string>
#include <vector>

#include "store.h"

namespace beverloo {

struct WorkerExit {
  std::int64_t attempt_id = 0;
  bool signaled = false;
  int code = 0;  ///< exit code, or the signal number if signaled
};

class Executor {
 public:
  virtual ~Executor() = default;
  virtual std::string name() const = 0;
  virtual int capacity() const = 0;
  virtual int running() const = 0;
  /// Starts a worker for the claimed job (spec.json is already written); returns its pid.
  virtual std::int64_t start(const ClaimedJob& job, const std::string& job_dir) = 0;
  /// Workers that ended since the last call.
  virtual std::vector<WorkerExit> reap() = 0;
  /// Asks every worker to checkpoint and stop (SIGTERM), then waits for them.
  virtual std::vector<WorkerExit> stop_all() = 0;
  /// Stops one worker the same way (timeouts).
  virtual void stop(std::int64_t attempt_id) = 0;
};

/// Worker processes on this machine: fork + exec of this binary's `worker` subcommand. The
/// child takes the job's flock before exec, so the lock exists exactly as long as the worker.
class LocalExecutor final : public Executor {
 public:
  static constexpr int kStopGraceSeconds = 30;  ///< SIGTERM, then SIGKILL after this
  explicit LocalExecutor(int workers) : capacity_(workers) {}
  std::string name() const override { return "local"; }
  int capacity() const override { return capacity_; }
  int running() const override { return static_cast<int>(children_.size()); }
  std::int64_t start(const ClaimedJob& job, const std::string& job_dir) override;
  std::vector<WorkerExit> reap() override;
  std::vector<WorkerExit> stop_all() override;
  void stop(std::int64_t attempt_id) override;

 private:
  struct Child {
    std::int64_t pid, attempt_id;
  };
  int capacity_;
  std::vector<Child> children_;
};

}  // namespace beverloo
