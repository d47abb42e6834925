#pragma once
/// \file store.h
/// \brief Every state change of a campaign, each one SQLite transaction. Only the coordinator
/// calls these (workers never open the database).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/failures.h"
#include "orchestrator/campaign/planner.h"
#include "orchestrator/db/database.h"
#include "orchestrator/sweep/sweep.h"

namespace beverloo {

/// Why an attempt failed; decides whether the job is retried and whether that costs a retry.
struct ClaimedJob {
  std::string key, dir, job_json, token;
  std::int64_t attempt_id = 0;
  int attempt_no = 0;
};

struct RunningAttempt {
  std::int64_t attempt_id;
  std::string key, dir, token, executor;
  std::int64_t pid;
  // Slurm attempts: their submission (-1: claimed but never handed to sbatch) and array index
  std::int64_t submission = -1;
  int array_task = -1;
  std::string job_json;  ///< the canonical job (its result is checked against it)
};

/// One sbatch call, as recorded before and after it ran.
struct SlurmSubmission {
  std::int64_t id = -1;
  std::string name, state, slurm_job_id;  ///< state: submitting | submitted | never_submitted
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
  /// Stores planner decisions in one transaction: each added job inserted (or, if it exists,
  /// shared) and linked to the campaign after its other jobs, and every decision's row.
  void record_decisions(std::int64_t campaign, const std::vector<PlanDecision>& decisions);
  /// The newest campaign, or -1.
  std::int64_t latest_campaign();

  /// The directories of finished jobs (of any campaign, this engine) on the trajectory of the
  /// job `key` (SimConfig::trajectory_json: they differ from it only in their stopping rules),
  /// the one that ran furthest first: checkpoints the job may continue (a job given more flow
  /// time). The engine decides whether it can (HopperRun::prepare); none: an empty list.
  std::vector<std::string> continuation_sources(const std::string& key);

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

  // Slurm submissions: recorded before sbatch runs (with the array index of each attempt) and
  // completed after it, each in one transaction.
  std::int64_t begin_submission(const std::string& name, int array_size, int throttle, const std::string& script,
                                const std::string& sbatch_args_json,
                                const std::vector<std::pair<std::int64_t, int>>& attempt_tasks);
  void submission_done(std::int64_t submission, const std::string& slurm_job_id);
  void submission_never_happened(std::int64_t submission, const std::string& message);
  SlurmSubmission submission(std::int64_t id);
  void set_slurm_state(std::int64_t attempt_id, const std::string& state, int restarts);
  /// heartbeat_at from the worker's heartbeat file (unix seconds).
  void heartbeat_at(std::int64_t attempt_id, double unix_seconds);
  StateCounts counts(std::int64_t campaign);
  /// Failed and cancelled jobs of the campaign back to pending (retry budget reset); returns how many.
  std::int64_t retry(std::int64_t campaign, bool include_cancelled);
  /// Pending jobs of the campaign to cancelled; returns how many.
  std::int64_t cancel(std::int64_t campaign);
  /// Pending jobs of the campaign expanded by another engine version (a campaign begun with an
  /// older binary): cancelled, never run by this one, whose results they would be stored as.
  /// The sweep expanded by this binary holds its own jobs for the same points. Returns how many.
  std::int64_t set_aside_other_engines(std::int64_t campaign);

 private:
  std::int64_t cancel_pending(std::int64_t campaign, bool other_engines_only);
  /// Inserts jobs (shared if they exist) and links them to the campaign from point_index on.
  void insert_and_link(std::int64_t campaign, const std::vector<const JobSpec*>& jobs, std::int64_t point_index);

 public:

 private:
  db::Database& db_;
};

/// A fresh 128-bit random token (hex), the fencing value of an attempt.
/// What a job's state means, in one phrase (report, `campaign status`, docs/database.md).
const char* job_state_meaning(const std::string& state);

std::string new_token();
std::string host_name();

}  // namespace beverloo
