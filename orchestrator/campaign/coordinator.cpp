#include "coordinator.h"
#include "core/atomic_file.h"
#include "core/cpus.h"
#include "core/disk_space.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <thread>

#include "engine/io/job_output.h"
#include "orchestrator/executors/executor_factory.h"
#include "job_files.h"
#include "core/failures.h"
#include "core/stop_signal.h"
#include "core/text_escape.h"
#include "orchestrator/db/migrations.h"
#include "store.h"
#include "core/version.h"

namespace beverloo {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

std::string last_log_line(const std::string& job_dir) {
  std::ifstream in(fs::path(job_dir) / job_files::kLog);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

FailureClass classify(const WorkerExit& e) { return failure_from_exit(e.signaled, e.code); }

class Coordinator {
 public:
  Coordinator(db::Database& db, std::int64_t campaign, const CampaignOptions& o, Executor& ex)
      : db_(db), store_(db), campaign_(campaign), o_(o), ex_(ex), host_(host_name()) {}

  int run(const std::atomic<bool>* stop) {
    // every attempt left in flight by an earlier coordinator is accounted for before anything new starts
    reconcile();
    // a campaign begun by another engine: its pending jobs are not this binary's to run
    if (const std::int64_t n = store_.set_aside_other_engines(campaign_))
      std::fprintf(stderr,
                   "[beverloo] %lld pending job(s) of another engine version cancelled: this is engine %s, whose own "
                   "jobs for the same points the sweep holds (campaign status lists the versions)\n",
                   (long long)n, BEVERLOO_VERSION);
    plan();  // decisions due from results stored before (a resumed adaptive campaign)
    const auto start = Clock::now();
    auto last_timeout_check = start;
    initial_ = store_.counts(campaign_);
    while (true) {
      if (stop->load()) return shutdown();
      if (!disk_full_.empty()) return stop_for_full_disk();
      std::vector<ClaimedJob> batch;  // fill free slots (the Slurm executor submits them as arrays)
      for (int free = ex_.free_slots(); free > 0; --free) {
        auto job = store_.claim_next(campaign_, ex_.name(), host_);
        if (!job) break;
        try {
          write_spec(*job);
        } catch (const std::exception& e) {
          // the job's directory cannot be made or written: this attempt fails as an I/O failure
          // (retried within the budget, then failed with this reason) and the campaign goes on;
          // for want of room it is disk_full, free, and the campaign stops
          const std::string why = std::string("cannot prepare the job directory: ") + e.what();
          const FailureClass cls = io_or_disk_full(job_dir(job->dir), why);
          const std::string state = store_.record_failure(job->attempt_id, job->key, cls, -1, why, o_.max_retries);
          log_event(*job, std::string(to_string(cls)) + " -> " + state, why);
          if (cls == FailureClass::DiskFull) break;  // claim nothing more: the loop stops
          continue;
        }
        batch.push_back(*job);
      }
      if (!batch.empty()) {
        for (const ClaimedJob& j : batch) live_[j.attempt_id] = {j, Clock::now()};
        ex_.start(batch);
      }
      const std::vector<WorkerExit> exits = ex_.poll();
      for (const WorkerExit& e : exits) finished(e);
      if (!exits.empty()) plan();
      if (Clock::now() - last_timeout_check > std::chrono::milliseconds(500)) {
        check_timeouts();
        last_timeout_check = Clock::now();
      }
      const StateCounts c = store_.counts(campaign_);
      progress(c, start, false);
      if (c.pending == 0 && ex_.in_flight() == 0) {
        progress(c, start, true);
        return c.failed > 0 ? exit_code::kJobsFailed : exit_code::kOk;
      }
      if (exits.empty() && batch.empty()) ex_.wait();  // something ended: claim the next job at once
    }
  }

 private:
  /// Asks the planner (if any) and stores its decisions with their jobs in one transaction. A
  /// planner that fails stops planning for this run, loudly; the jobs already there still run.
  void plan() {
    if (!o_.planner || planner_failed_) return;
    try {
      const std::vector<PlanDecision> decisions = o_.planner->plan(db_, campaign_);
      store_.record_decisions(campaign_, decisions);
      for (const PlanDecision& d : decisions)
        std::fprintf(stderr, "[beverloo] adaptive %s %s: %s\n", d.series_key.substr(0, 12).c_str(),
                     d.job ? ("add " + d.job->key.substr(0, 12)).c_str() : "stop", terminal_safe(d.reason).c_str());
    } catch (const std::exception& e) {
      planner_failed_ = true;
      std::fprintf(stderr, "[beverloo] adaptive planner failed, no more jobs will be added in this run: %s\n",
                   terminal_safe(e.what()).c_str());
    }
  }

  std::string job_dir(const std::string& dir) const { return (fs::path(o_.dir) / dir).string(); }

  void write_spec(const ClaimedJob& job) {
    const std::string dir = job_dir(job.dir);
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(dir, ec);
    if (fs::exists(st) && !fs::is_directory(st)) {
      // something that is not a directory where the job's directory belongs (jobs/ is ours):
      // kept aside under another name, and the job runs again in a directory of its own
      const std::string aside = dir + ".not-a-directory";
      fs::rename(dir, aside);
      std::fprintf(stderr, "[beverloo] %s was not a directory; moved to %s\n", terminal_safe(dir).c_str(), terminal_safe(aside).c_str());
    }
    fs::create_directories(dir);
    job_files::write_spec(dir, {job.key, job.attempt_no, job.token, o_.heartbeat_s, o_.threads,
                                nlohmann::json::parse(job.job_json), continuation_of(job)});
  }

  /// A job with no checkpoint of its own that only stops later than a finished job of its
  /// trajectory (more flow time for a point) continues that job's final checkpoint: the path the
  /// worker is given, relative to the job's directory ("" for none).
  std::string continuation_of(const ClaimedJob& job) {
    const fs::path own = fs::path(job_dir(job.dir)) / job_output::kCheckpoint;
    if (fs::exists(own)) return "";
    for (const std::string& source : store_.continuation_sources(job.key)) {
      const fs::path rel = fs::path(source);
      if (rel.parent_path() != fs::path(job.dir).parent_path()) continue;  // siblings under jobs/ only
      if (!fs::exists(fs::path(job_dir(source)) / job_output::kCheckpoint)) continue;
      const std::string path = (fs::path("..") / rel.filename() / job_output::kCheckpoint).string();
      log_event(job, "continues", "the run of " + source + " (the same trajectory, stopped earlier)");
      return path;
    }
    return "";
  }

  /// An attempt has ended: decide from its files first (outcome.json with its token), then from
  /// what the executor saw (the worker's exit status, or the scheduler's verdict).
  void settle(const ClaimedJob& job, const WorkerExit* exit) {
    const std::string dir = job_dir(job.dir);
    const auto outcome = job_files::read_outcome(dir);
    const bool ours = outcome && outcome->token == job.token;
    std::string damaged;
    if (ours && outcome->exit_code == exit_code::kOk) {
      try {  // the engine says whether its files are complete and intact
        const job_output::CompletedRun r =
            job_output::read_completed(dir, SimConfig::from_json(nlohmann::json::parse(job.job_json)), outcome->files);
        store_.ingest_success(job, r.summary_json, r.h, r.v_g, r.v_g_err);
        log_event(job, "done", "");
        return;
      } catch (const std::exception& e) {
        // a success whose files are damaged, missing or changed: an I/O failure, retried; the
        // files go, so that the retry runs the job (from its checkpoint) instead of finding them
        damaged = e.what();
        job_output::remove_result(dir);
      }
    }
    FailureClass cls = FailureClass::Lost;
    int status = -1;
    std::string message = "worker gone without an outcome (killed, or the coordinator died before it started)";
    const FailureClass* verdict = exit && exit->verdict ? &*exit->verdict : nullptr;  // (a pointer: GCC 12 warns falsely on an optional copy)
    if (!damaged.empty()) {
      cls = FailureClass::Io;
      status = outcome->exit_code;
      message = "the worker reported success but its result is unusable: " + damaged;
    } else if (ours) {
      cls = class_of(outcome->failure_class);
      status = outcome->exit_code;
      message = outcome->message;
      // a worker stopped by a signal cannot tell a time limit from a preemption; the scheduler can
      if (cls == FailureClass::Interrupted && verdict && is_scheduler_stop(*verdict)) {
        cls = *verdict;
        message = exit->message + " (" + message + ")";
      }
    } else if (verdict) {
      cls = *verdict;
      message = exit->message;
    } else if (exit && exit->have_status) {
      cls = classify(*exit);
      status = exit->signaled ? 128 + exit->code : exit->code;
      message = exit->signaled ? "worker killed by signal " + std::to_string(exit->code) : last_log_line(dir);
    }
    if (cls == FailureClass::Io) cls = io_or_disk_full(dir, message, /*settled_late=*/exit == nullptr);
    if (timed_out_.erase(job.attempt_id) && cls == FailureClass::Interrupted) {
      cls = FailureClass::Timeout;
      message = "exceeded the job timeout of " + std::to_string(o_.job_timeout_s) + " s; will resume from its checkpoint";
    }
    if (is_infrastructure(cls) && ++infra_failures_[job.key] > o_.max_infra_retries) {
      message += " (infrastructure retry limit reached)";
      cls = FailureClass::Internal;
    }
    const std::string state = store_.record_failure(job.attempt_id, job.key, cls, status, message, o_.max_retries);
    log_event(job, std::string(to_string(cls)) + " -> " + state, message);
  }

  /// An I/O failure is disk_full when the file system holding `dir` has no room (core/disk_space.h):
  /// the job is not charged, and the campaign stops claiming (disk_full_) until someone makes room.
  /// settled_late: an attempt an earlier coordinator left (a worker that outlived the coordinator
  /// of a full disk and wrote its outcome after it): its failure was for want of room then, but
  /// the claims stop only if the disk is still full now (someone may have made room since).
  FailureClass io_or_disk_full(const std::string& dir, const std::string& message, bool settled_late = false) {
    if (!no_space_left(dir, message)) return FailureClass::Io;
    if (disk_full_.empty() && (!settled_late || file_system_full(dir))) disk_full_ = dir;
    return FailureClass::DiskFull;
  }

  /// Stops the workers (each writes a checkpoint if it still can) and ends the run with the
  /// I/O exit code; the same command resumes the campaign once there is room.
  int stop_for_full_disk() {
    std::fprintf(stderr,
                 "\n[beverloo] stopping: the disk is full (no space left for %s); make room and run the same "
                 "command again: the jobs resume from their checkpoints\n",
                 terminal_safe(disk_full_).c_str());
    for (const WorkerExit& e : ex_.stop_all()) finished(e);
    return exit_code::kIo;
  }

  static FailureClass class_of(const std::string& failure_class) {
    return failure_from_name(failure_class).value_or(FailureClass::Internal);
  }
  static bool is_scheduler_stop(FailureClass c) {
    return c == FailureClass::Timeout || c == FailureClass::Preempted || c == FailureClass::NodeFailure ||
           c == FailureClass::Cancelled || c == FailureClass::Stalled;
  }

  void finished(const WorkerExit& e) {
    auto it = live_.find(e.attempt_id);
    if (it == live_.end()) return;
    const ClaimedJob job = it->second.job;
    live_.erase(it);
    settle(job, &e);
  }

  /// Attempts that an earlier coordinator left running: the executor adopts the live ones (and
  /// reports them when they end); the dead ones are settled from their files now.
  void reconcile() {
    for (const RunningAttempt& a : store_.running_attempts()) {
      if (a.executor != ex_.name())
        throw CampaignBusy("attempt " + std::to_string(a.attempt_id) + " of this campaign is still in flight on the '" +
                           a.executor + "' executor; run with --executor " + a.executor + " until it has been collected");
      ClaimedJob job;
      job.key = a.key;
      job.dir = a.dir;
      job.token = a.token;
      job.attempt_id = a.attempt_id;
      job.job_json = a.job_json;
      if (ex_.adopt(a))
        live_[a.attempt_id] = {job, Clock::now()};
      else
        settle(job, nullptr);
    }
  }

  void check_timeouts() {
    if (o_.job_timeout_s <= 0) return;
    for (auto& [id, l] : live_)
      if (!timed_out_.count(id) && std::chrono::duration<double>(Clock::now() - l.started).count() > o_.job_timeout_s) {
        timed_out_.insert(id);
        ex_.stop(id);
      }
  }

  int shutdown() {
    std::fprintf(stderr, "\n[beverloo] stopping: %s\n", ex_.on_stop().c_str());
    for (const WorkerExit& e : ex_.stop_all()) finished(e);
    return exit_code::kInterrupted;
  }

  void log_event(const ClaimedJob& job, const std::string& what, const std::string& message) {
    if (o_.progress != ProgressMode::Log) return;
    std::fprintf(stderr, "[beverloo] job %s %s%s%s\n", job.key.substr(0, 12).c_str(), what.c_str(),
                 message.empty() ? "" : ": ", terminal_safe(message).c_str());
  }

  void progress(const StateCounts& c, Clock::time_point start, bool final_line) {
    if (o_.progress == ProgressMode::Quiet) return;
    const auto now = Clock::now();
    const bool terminal = o_.progress == ProgressMode::Terminal;
    // log mode: every finished job has its own line; the summary comes once a minute
    if (!final_line && now - last_progress_ < std::chrono::milliseconds(terminal ? 250 : 60000)) return;
    last_progress_ = now;
    const double minutes = std::chrono::duration<double>(now - start).count() / 60;
    const double finished_now = c.finished() - initial_.finished();
    const double rate = minutes > 0 ? finished_now / minutes : 0;
    const double eta = rate > 0 ? (c.pending + c.running) / rate : NAN;
    char line[256];
    std::snprintf(line, sizeof line, "jobs %lld/%lld finished (%lld done, %lld clogged, %lld failed), %lld running, %lld pending | %.2f jobs/min | ETA %s",
                  (long long)c.finished(), (long long)c.total(), (long long)c.done, (long long)c.clogged,
                  (long long)c.failed, (long long)c.running, (long long)c.pending, rate,
                  std::isfinite(eta) ? (std::to_string(static_cast<long>(eta * 60)) + " s").c_str() : "?");
    if (terminal)
      std::fprintf(stderr, "\r\033[K%s%s", line, final_line ? "\n" : "");
    else
      std::fprintf(stderr, "[beverloo] %s\n", line);
  }

  struct Live {
    ClaimedJob job;
    Clock::time_point started;
  };
  db::Database& db_;
  CampaignStore store_;
  std::int64_t campaign_;
  CampaignOptions o_;
  Executor& ex_;
  std::string host_;
  std::map<std::int64_t, Live> live_;  // started or adopted, not yet settled
  std::set<std::int64_t> timed_out_;  // attempts stopped for exceeding --job-timeout
  std::map<std::string, int> infra_failures_;
  bool planner_failed_ = false;
  std::string disk_full_;  // a directory an attempt could not write for want of room: stop claiming
  StateCounts initial_;
  Clock::time_point last_progress_{};
};

}  // namespace

int run_campaign(const std::optional<std::string>& sweep_path, const CampaignOptions& opt) {
  CampaignOptions o = opt;
  // threads per job: locally workers x threads must fit the cores (oversubscribed threads only
  // slow every job down); on Slurm each array task asks for them (--cpus-per-task)
  if (o.threads < 1) throw ConfigError("--threads", "must be at least 1");
  if (o.workers <= 0) o.workers = std::max(1, usable_cpus() / o.threads);
  // (more single-threaded workers than cores stays allowed, as before: they only queue)
  if (o.executor == "local" && o.threads > 1) check_threads("--threads", o.threads, o.workers);
  check_executor_options(o.executor, o.executor_options);  // another executor's option: refused before anything is written
  if (o.progress == ProgressMode::Auto) o.progress = isatty(STDERR_FILENO) ? ProgressMode::Terminal : ProgressMode::Log;
  // Parse and expand before touching the directory: a bad sweep writes nothing.
  std::optional<Sweep> sweep;
  std::vector<JobSpec> jobs;
  std::string text;
  if (sweep_path) {
    sweep = Sweep::load(*sweep_path, &text);
    jobs = sweep->expand();
  }
  // without a sweep there is nothing to create: a missing campaign is an error, not a new directory
  CampaignWriter writer(o.dir, sweep ? CampaignWriter::Open::CreateIfMissing : CampaignWriter::Open::MustExist);
  db::Database& db = writer.db();
  CampaignStore store(db);
  const std::int64_t campaign = sweep ? store.create_campaign(*sweep, text, jobs) : store.latest_campaign();
  if (campaign < 0) throw SweepError(o.dir, "holds no campaign; give a sweep file");
  const std::atomic<bool>* stop = install_stop_handlers();
  sigset_t chld;  // queued for wait_for_event(); workers unblock it before exec
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  sigprocmask(SIG_BLOCK, &chld, nullptr);
  const std::unique_ptr<Executor> ex =
      make_executor(o.executor, store, ExecutorSettings{.campaign_dir = o.dir, .workers = o.workers, .threads = o.threads,
                                                        .heartbeat_s = o.heartbeat_s, .options = o.executor_options});
  Coordinator c(db, campaign, o, *ex);
  return c.run(stop);
}

}  // namespace beverloo
