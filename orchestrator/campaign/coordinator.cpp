#include "coordinator.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "engine/io/h5.h"
#include "executor.h"
#include "job_files.h"
#include "orchestrator/cli/exit_codes.h"
#include "orchestrator/cli/signals.h"
#include "orchestrator/db/migrations.h"
#include "store.h"

namespace beverloo {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

CoordinatorLock::CoordinatorLock(const std::string& dir) {
  const std::string path = (fs::path(dir) / "coordinator.lock").string();
  fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);  // CLOEXEC: workers must not inherit it
  if (fd_ < 0) throw IoError("cannot open " + path);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    std::ifstream in(path);
    std::string holder;
    std::getline(in, holder);
    ::close(fd_);
    fd_ = -1;
    throw CampaignBusy("another coordinator is running this campaign (" + holder + "); wait for it or stop it");
  }
  // a dead holder's lock is gone with its process: we own it now; say who we are
  std::ostringstream me;
  me << "host " << host_name() << ", pid " << ::getpid() << ", since " << std::time(nullptr);
  const std::string text = me.str() + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) < 0) { /* informational only */ }
}

CoordinatorLock::~CoordinatorLock() {
  if (fd_ >= 0) ::close(fd_);
}

namespace {

struct Profile {
  std::vector<double> h, v_g, v_g_err;
};

Profile read_profile(const std::string& job_dir) {
  H5Handle f = h5::open_file((fs::path(job_dir) / "result.h5").string());
  H5Handle g = h5::open_group(f, "profile");
  return {h5::read_doubles(g, "h"), h5::read_doubles(g, "v_g"), h5::read_doubles(g, "v_g_err")};
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string last_log_line(const std::string& job_dir) {
  std::ifstream in(fs::path(job_dir) / job_files::kLog);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

FailureClass classify(const WorkerExit& e) {
  if (e.signaled) return FailureClass::Killed;
  switch (e.code) {
    case exit_code::kConfig: return FailureClass::InvalidParameters;
    case exit_code::kUnstable: return FailureClass::BlowUp;
    case exit_code::kIo: return FailureClass::Io;
    case exit_code::kInterrupted: return FailureClass::Interrupted;
    case job_files::kLockBusyExit: return FailureClass::Lost;
    default: return FailureClass::Internal;
  }
}

class Coordinator {
 public:
  Coordinator(db::Database& db, std::int64_t campaign, const CampaignOptions& o, Executor& ex)
      : db_(db), store_(db), campaign_(campaign), o_(o), ex_(ex), host_(host_name()) {}

  int run(const std::atomic<bool>* stop) {
    reconcile();
    const auto start = Clock::now();
    auto last_adopt_check = start, last_heartbeat = start;
    initial_ = store_.counts(campaign_);
    while (true) {
      if (stop->load()) return shutdown();
      // fill free worker slots
      while (ex_.running() < ex_.capacity()) {
        auto job = store_.claim_next(campaign_, ex_.name(), host_);
        if (!job) break;
        launch(*job);
      }
      const std::vector<WorkerExit> exits = ex_.reap();
      for (const WorkerExit& e : exits) finished(e);
      if (Clock::now() - last_adopt_check > std::chrono::milliseconds(500)) {
        check_adopted();
        check_timeouts();
        last_adopt_check = Clock::now();
      }
      if (std::chrono::duration<double>(Clock::now() - last_heartbeat).count() > o_.heartbeat_s) {
        record_heartbeats();
        last_heartbeat = Clock::now();
      }
      const StateCounts c = store_.counts(campaign_);
      progress(c, start, false);
      if (c.pending == 0 && ex_.running() == 0 && adopted_.empty()) {
        progress(c, start, true);
        return c.failed > 0 ? exit_code::kJobsFailed : exit_code::kOk;
      }
      if (exits.empty()) wait_for_event();  // something ended: claim the next job at once
    }
  }

 private:
  std::string job_dir(const std::string& dir) const { return (fs::path(o_.dir) / dir).string(); }

  /// Sleeps until a worker exits (SIGCHLD, blocked so that it queues) or 100 ms pass, so that a
  /// finished job is ingested and the next one started at once rather than on a polling tick.
  static void wait_for_event() {
    sigset_t chld;
    sigemptyset(&chld);
    sigaddset(&chld, SIGCHLD);
    const timespec timeout{0, 100'000'000};
    sigtimedwait(&chld, nullptr, &timeout);
  }

  void launch(const ClaimedJob& job) {
    const std::string dir = job_dir(job.dir);
    fs::create_directories(dir);
    const nlohmann::json spec = {{"key", job.key},
                                 {"attempt_no", job.attempt_no},
                                 {"token", job.token},
                                 {"job", nlohmann::json::parse(job.job_json)}};
    write_text_atomically((fs::path(dir) / job_files::kSpec).string(), spec.dump(2) + "\n");
    const std::int64_t pid = ex_.start(job, dir);
    store_.set_attempt_pid(job.attempt_id, pid);
    live_[job.attempt_id] = {job, Clock::now()};
  }

  /// An attempt has ended (its worker exited, or its lock was released): decide from the files.
  void settle(const ClaimedJob& job, const WorkerExit* exit) {
    const std::string dir = job_dir(job.dir);
    const auto outcome = job_files::read_outcome(dir);
    const bool ours = outcome && outcome->token == job.token;
    if (ours && outcome->exit_code == exit_code::kOk) {
      const Profile p = read_profile(dir);
      store_.ingest_success(job, read_text(fs::path(dir) / "summary.json"), p.h, p.v_g, p.v_g_err);
      log_event(job, "done", "");
      return;
    }
    FailureClass cls;
    int status;
    std::string message;
    if (exit) {
      cls = classify(*exit);
      status = exit->signaled ? 128 + exit->code : exit->code;
      message = exit->signaled ? "worker killed by signal " + std::to_string(exit->code) : last_log_line(dir);
    } else {  // adopted or found dead after a coordinator restart: only the files can tell
      cls = ours ? FailureClass::Internal : FailureClass::Lost;
      status = ours ? outcome->exit_code : -1;
      message = ours ? outcome->message : "worker gone without an outcome (killed, or the coordinator died before it started)";
      if (ours) {
        if (outcome->failure_class == "blow_up") cls = FailureClass::BlowUp;
        else if (outcome->failure_class == "invalid_parameters") cls = FailureClass::InvalidParameters;
        else if (outcome->failure_class == "io") cls = FailureClass::Io;
        else if (outcome->failure_class == "interrupted") cls = FailureClass::Interrupted;
      }
    }
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

  void finished(const WorkerExit& e) {
    auto it = live_.find(e.attempt_id);
    if (it == live_.end()) return;
    const ClaimedJob job = it->second.job;
    live_.erase(it);
    settle(job, &e);
  }

  /// Attempts that an earlier coordinator left running: adopt live workers, settle dead ones.
  void reconcile() {
    for (const RunningAttempt& a : store_.running_attempts()) {
      ClaimedJob job;
      job.key = a.key;
      job.dir = a.dir;
      job.token = a.token;
      job.attempt_id = a.attempt_id;
      if (job_files::lock_is_held(job_dir(a.dir)))
        adopted_[a.attempt_id] = job;
      else
        settle(job, nullptr);
    }
  }

  void check_adopted() {
    for (auto it = adopted_.begin(); it != adopted_.end();) {
      if (job_files::lock_is_held(job_dir(it->second.dir))) {
        ++it;
        continue;
      }
      const ClaimedJob job = it->second;
      it = adopted_.erase(it);
      settle(job, nullptr);
    }
  }

  /// attempts.heartbeat_at: when each worker was last seen alive (holding its job's lock).
  void record_heartbeats() {
    for (const auto& [id, l] : live_)
      if (job_files::lock_is_held(job_dir(l.job.dir))) store_.heartbeat(id);
    for (const auto& [id, job] : adopted_)
      if (job_files::lock_is_held(job_dir(job.dir))) store_.heartbeat(id);
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
    std::fprintf(stderr, "\n[beverloo] stopping: workers checkpoint and stop\n");
    for (const WorkerExit& e : ex_.stop_all()) finished(e);
    return exit_code::kInterrupted;
  }

  void log_event(const ClaimedJob& job, const std::string& what, const std::string& message) {
    if (o_.progress != ProgressMode::Log) return;
    std::fprintf(stderr, "[beverloo] job %s %s%s%s\n", job.key.substr(0, 12).c_str(), what.c_str(),
                 message.empty() ? "" : ": ", message.c_str());
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
  std::map<std::int64_t, Live> live_;
  std::map<std::int64_t, ClaimedJob> adopted_;
  std::set<std::int64_t> timed_out_;  // attempts stopped for exceeding --job-timeout
  std::map<std::string, int> infra_failures_;
  StateCounts initial_;
  Clock::time_point last_progress_{};
};

}  // namespace

int run_campaign(const std::optional<std::string>& sweep_path, const CampaignOptions& opt) {
  CampaignOptions o = opt;
  if (o.workers <= 0) o.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (o.progress == ProgressMode::Auto) o.progress = isatty(STDERR_FILENO) ? ProgressMode::Terminal : ProgressMode::Log;
  // Parse and expand before touching the directory: a bad sweep writes nothing.
  std::optional<Sweep> sweep;
  std::vector<JobSpec> jobs;
  std::string text;
  if (sweep_path) {
    sweep = Sweep::load(*sweep_path, &text);
    jobs = sweep->expand();
  }
  fs::create_directories(fs::path(o.dir) / "jobs");
  CoordinatorLock lock(o.dir);
  db::Database db((fs::path(o.dir) / "campaign.sqlite").string(), db::Database::Mode::ReadWrite);
  db::open_store(db);
  CampaignStore store(db);
  const std::int64_t campaign = sweep ? store.create_campaign(*sweep, text, jobs) : store.latest_campaign();
  if (campaign < 0) throw SweepError(o.dir, "holds no campaign; give a sweep file");
  const std::atomic<bool>* stop = install_stop_handlers();
  sigset_t chld;  // queued for wait_for_event(); workers unblock it before exec
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  sigprocmask(SIG_BLOCK, &chld, nullptr);
  LocalExecutor ex(o.workers);
  Coordinator c(db, campaign, o, ex);
  return c.run(stop);
}

}  // namespace beverloo
