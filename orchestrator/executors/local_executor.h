#pragma once
/// \file local_executor.h
/// \brief Worker processes on this machine (executor "local").
#include <cstdint>
#include <string>
#include <vector>

#include "executor.h"

namespace beverloo {

/// Worker processes on this machine: fork + exec of this binary's `worker` subcommand. The
/// child takes the job's flock before exec, so the lock exists exactly as long as the worker.
class LocalExecutor final : public Executor {
 public:
  static constexpr int kStopGraceSeconds = 30;  ///< SIGTERM, then SIGKILL after this
  LocalExecutor(CampaignStore& store, std::string campaign_dir, int workers, double heartbeat_s)
      : store_(store), dir_(std::move(campaign_dir)), capacity_(workers), heartbeat_s_(heartbeat_s) {}
  std::string name() const override { return "local"; }
  std::string on_stop() const override { return "workers checkpoint and stop"; }
  int free_slots() const override { return capacity_ - static_cast<int>(children_.size()); }
  int in_flight() const override { return static_cast<int>(children_.size() + adopted_.size()); }
  void start(const std::vector<ClaimedJob>& jobs) override;
  bool adopt(const RunningAttempt& a) override;
  std::vector<WorkerExit> poll() override;
  void wait() override;
  std::vector<WorkerExit> stop_all() override;
  void stop(std::int64_t attempt_id) override;

 private:
  struct Child {
    std::int64_t pid, attempt_id;
    std::string dir;
  };
  std::vector<WorkerExit> reap();
  CampaignStore& store_;
  std::string dir_;
  int capacity_;
  double heartbeat_s_;
  std::vector<Child> children_;
  std::vector<Child> adopted_;  ///< workers of an earlier coordinator: watched through their locks
  double last_heartbeat_ = 0;
};

}  // namespace beverloo
