#pragma once
/// \file store.h
/// \brief Every state change of a campaign, each one SQLite transaction. Only the coordinator
/// calls these (workers never open the database).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/db/database.h"
#include "orchestrator/sweep/sweep.h"

namespace beverloo {

/// Why an attempt failed; decides whether the job is retried and whether that costs a retry.
enum class FailureClass { InvalidParameters, BlowUp, Killed, Timeout, Io, Interrupted, Lost, Internal };
const char* to_string(FailureClass c);
/// Infrastructure failures (killed, lost, interrupted, timeout) resume from the checkpoint
/// without using up the job's retry budget.
bool is_infrastructure(FailureClass c);

struct ClaimedJob {
  std::string key, dir, job_json, token;
  std::int64_t attempt_id = 0;
  int attempt_no = 0;
};

struct RunningAttempt {
  std::int64_t attempt_id;
  std::string key, dir, token, executor;
  std::int64_t pid;
};

struct StateCounts {
  std::int64_t pending = 0, running = 0, done = 0, clogged = 0, failed = 0, cancelled = 0;
  std::int64_t total() const { return pending + running + done + clogged + failed + cancelled; }
  std::int64_t finished() const { return done + clogged + failed + cancelled; }
};

class CampaignStore {
 public:
  explicit CampaignStore(db::Database& db) : db_(db) {}

  /// Creates the campaign (or finds the same name + sweep) and inserts its jobs, all in one
  /// transaction; jobs that exist already (from any campaign) are shared, not duplicated.
  std::int64_t create_campaign(const Sweep& sweep, const std::string& sweep_text, const std::vector<JobSpec>& jobs);
  /// The newest campaign, or -1.
  std::int64_t latest_campaign();

  /// Takes the next pending job of the campaign and records a new running attempt for it.
  std::optional<ClaimedJob> claim_next(std::int64_t campaign, const std::string& executor, const std::string& host);
  void set_attempt_pid(std::int64_t attempt_id, std::int64_t pid);
  void heartbeat(std::int64_t attempt_id);

  /// Ingests a finished job in one idempotent transaction: results + profile rows, the
  /// attempt succeeded, the job done or clogged. A second call for the same job changes nothing.
  void ingest_success(const ClaimedJob& a, const std::string& summary_json, const std::vector<double>& h,
                      const std::vector<double>& v_g, const std::vector<double>& v_g_err);
  /// Records a failed attempt and decides the job's next state (pending again, or failed).
  /// Returns the job's new state.
  std::string record_failure(std::int64_t attempt_id, const std::string& key, FailureClass cls, int exit_status,
                             const std::string& message, int max_retries);

  std::vector<RunningAttempt> running_attempts();
  StateCounts counts(std::int64_t campaign);
  /// Failed and cancelled jobs of the campaign back to pending (retry budget reset); returns how many.
  std::int64_t retry(std::int64_t campaign, bool include_cancelled);
  /// Pending jobs of the campaign to cancelled; returns how many.
  std::int64_t cancel(std::int64_t campaign);

 private:
  db::Database& db_;
};

/// A fresh 128-bit random token (hex), the fencing value of an attempt.
std::string new_token();
std::string host_name();

}  // namespace beverloo
