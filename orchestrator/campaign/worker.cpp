#include "worker.h"

#include <new>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "engine/io/job_output.h"
#include "engine/protocol/run_hopper.h"
#include "job_files.h"
#include "core/cpus.h"
#include "core/failures.h"
#include "core/stop_signal.h"
#include "store.h"

namespace beverloo {
namespace fs = std::filesystem;

namespace {

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : fallback;
}

/// Rewrites heartbeat.json every interval while an attempt runs (its own thread: the engine
/// only publishes its step counter).
class HeartbeatWriter {
 public:
  HeartbeatWriter(std::string dir, std::string token, double interval_s, const std::atomic<std::int64_t>& step)
      : dir_(std::move(dir)), step_(step), interval_(interval_s) {
    hb_.token = std::move(token);
    hb_.host = host_name();
    hb_.pid = static_cast<long>(::getpid());
    const std::string array = env_or("SLURM_ARRAY_JOB_ID", ""), task = env_or("SLURM_ARRAY_TASK_ID", "");
    if (!array.empty()) hb_.slurm_job = array + "_" + task;
    const std::string restarts = env_or("SLURM_RESTART_COUNT", "");
    hb_.slurm_restarts = !array.empty() ? (restarts.empty() ? 0 : std::atoi(restarts.c_str())) : -1;
    write();
    thread_ = std::thread([this] { loop(); });
  }
  ~HeartbeatWriter() {
    {
      std::lock_guard<std::mutex> lock(m_);
      done_ = true;
    }
    cv_.notify_one();
    thread_.join();
  }

 private:
  void loop() {
    std::unique_lock<std::mutex> lock(m_);
    while (!cv_.wait_for(lock, std::chrono::duration<double>(interval_), [this] { return done_; })) write();
  }
  void write() {
    hb_.unix_time = unix_now();
    hb_.step = step_.load(std::memory_order_relaxed);
    try {
      job_files::write_heartbeat(dir_, hb_);
    } catch (const std::exception& e) {  // a full disk must not kill the run; the coordinator will see it stall
      std::fprintf(stderr, "beverloo worker: cannot write the heartbeat: %s\n", e.what());
    }
  }
  std::string dir_;
  const std::atomic<std::int64_t>& step_;
  double interval_;
  job_files::Heartbeat hb_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

/// One attempt in its job directory: the engine run, resumed from a checkpoint if there is one,
/// ending with outcome.json (written last, atomically, with the attempt's token).
int run_attempt(const std::string& dir, const job_files::Spec& spec, const std::atomic<bool>* stop) {
  job_files::Outcome out;
  out.token = spec.token;
  out.attempt_no = spec.attempt_no;
  // success, or a failure class: its exit code and name come from the one table (core/failures.h)
  auto finish = [&](std::optional<FailureClass> failure, const std::string& message) {
    const int code = failure ? failure_info(*failure).exit_code : exit_code::kOk;
    out.exit_code = code;
    out.failure_class = failure ? std::string(to_string(*failure)) : "";
    out.message = message;
    try {
      job_files::write_outcome(dir, out);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "beverloo worker: cannot write the outcome: %s\n", e.what());
      return exit_code::kIo;
    }
    if (!message.empty()) std::fprintf(stderr, "beverloo worker: %s\n", message.c_str());
    return code;
  };
  SimConfig c;
  try {
    c = SimConfig::from_json(spec.job);
  } catch (const ConfigError& e) {
    return finish(FailureClass::InvalidParameters, e.what());
  }
  std::atomic<std::int64_t> step{0};
  HeartbeatWriter heartbeat(dir, out.token, spec.heartbeat_s, step);
  try {
    // A previous attempt may have finished the run and died before writing its outcome.
    const job_output::ResultCheck done = job_output::check_result(dir, c);
    if (done.state == job_output::ResultState::Complete) {
      out.files = job_output::result_digests(dir);
      return finish(std::nullopt, "");
    }
    if (done.state != job_output::ResultState::None) {
      // damaged, or another job's: run it again (from the checkpoint if there is one)
      std::fprintf(stderr, "beverloo worker: %s; running the job again\n", done.reason.c_str());
      job_output::remove_result(dir);
    }
    RunOptions opt;
    opt.output_dir = dir;
    opt.resume = true;
    if (!spec.continue_from.empty()) opt.continue_from = (fs::path(dir) / spec.continue_from).string();
    opt.progress = ProgressMode::Log;
    opt.stop_request = stop;
    opt.progress_step = &step;
    // the threads asked for, but never more than this process may run on (a node that grants
    // fewer CPUs): the result is the same for every count
    opt.threads = std::min(spec.threads, usable_cpus());
    const RunResult r = run_hopper(c, opt);
    if (r.status == "interrupted") return finish(FailureClass::Interrupted, r.stop_reason);
    out.files = job_output::result_digests(dir);  // the bytes just written, for the coordinator to check
    return finish(std::nullopt, "");
  } catch (const ConfigError& e) {
    return finish(FailureClass::InvalidParameters, e.what());
  } catch (const InstabilityError& e) {
    return finish(FailureClass::BlowUp, e.what());
  } catch (const IoError& e) {
    return finish(FailureClass::Io, e.what());
  } catch (const std::bad_alloc&) {  // the node's memory or the job's limit: a budgeted retry, not a bug
    return finish(FailureClass::OutOfMemory, "an allocation failed (the node's memory, or the job's limit)");
  } catch (const std::exception& e) {
    return finish(FailureClass::Internal, e.what());
  }
}

bool read_json(const std::string& path, nlohmann::json& j) {
  std::ifstream in(path);
  if (!in) return false;
  try {
    j = nlohmann::json::parse(in);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

/// stdout and stderr to the job's log for the duration of one attempt (array tasks run several).
class LogRedirect {
 public:
  explicit LogRedirect(const std::string& dir) {
    std::fflush(stdout);
    std::fflush(stderr);
    saved_out_ = ::dup(STDOUT_FILENO);
    saved_err_ = ::dup(STDERR_FILENO);
    const int fd = ::open((fs::path(dir) / job_files::kLog).c_str(), O_CREAT | O_WRONLY | O_APPEND | O_CLOEXEC, 0644);
    if (fd >= 0) {
      ::dup2(fd, STDOUT_FILENO);
      ::dup2(fd, STDERR_FILENO);
      ::close(fd);
    }
  }
  ~LogRedirect() {
    std::fflush(stdout);
    std::fflush(stderr);
    ::dup2(saved_out_, STDOUT_FILENO);
    ::dup2(saved_err_, STDERR_FILENO);
    ::close(saved_out_);
    ::close(saved_err_);
  }

 private:
  int saved_out_ = -1, saved_err_ = -1;
};

/// A superseded attempt (stalled, cancelled) may still hold the job for Slurm's KillWait: wait
/// for it rather than give up the task at once.
constexpr double kLockWaitSeconds = 120;

bool lock_within(int fd, double seconds, const std::atomic<bool>* stop) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (stop->load() || std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  return true;
}



}  // namespace

int run_worker(const std::string& spec_path) {
  const std::string dir = fs::path(spec_path).parent_path().string();
  const job_files::SpecRead read = job_files::read_spec(spec_path);
  if (read.unreadable) {
    std::fprintf(stderr, "beverloo worker: cannot read %s\n", spec_path.c_str());
    return exit_code::kIo;
  }
  if (!read.spec) {
    std::fprintf(stderr, "beverloo worker: %s: %s\n", spec_path.c_str(), read.problem.c_str());
    return exit_code::kConfig;
  }
  return run_attempt(dir, *read.spec, install_stop_handlers());
}

int run_worker_task(const std::string& manifest_path, int task_index) {
  const std::atomic<bool>* stop = install_stop_handlers();
  nlohmann::json manifest;
  if (!read_json(manifest_path, manifest) || !manifest.contains("tasks") || !manifest.contains("root")) {
    std::fprintf(stderr, "beverloo worker: cannot read the manifest %s\n", manifest_path.c_str());
    return exit_code::kIo;
  }
  // the manifest's shape, before anything is read from it (a damaged one: a message, not an abort)
  auto entries_ok = [](const nlohmann::json& list) {
    if (!list.is_array()) return false;
    for (const auto& e : list)
      if (!e.is_object() || !e.contains("dir") || !e["dir"].is_string() || !e.contains("token") || !e["token"].is_string())
        return false;
    return true;
  };
  if (!manifest.is_object() || !manifest["tasks"].is_array() || !manifest["root"].is_string() ||
      (task_index >= 0 && task_index < static_cast<int>(manifest["tasks"].size()) && !entries_ok(manifest["tasks"][task_index]))) {
    std::fprintf(stderr, "beverloo worker: %s: not a manifest of {\"root\": text, \"tasks\": [[{\"dir\", \"token\"}, ...], ...]}\n",
                 manifest_path.c_str());
    return exit_code::kConfig;
  }
  const nlohmann::json& tasks = manifest.at("tasks");
  if (task_index < 0 || task_index >= static_cast<int>(tasks.size())) {
    std::fprintf(stderr, "beverloo worker: task %d is not in %s (%zu tasks)\n", task_index, manifest_path.c_str(), tasks.size());
    return exit_code::kConfig;
  }
  const fs::path root = manifest.at("root").get<std::string>();
  int status = exit_code::kOk;
  for (const nlohmann::json& entry : tasks.at(task_index)) {
    const std::string dir = (root / entry.at("dir").get<std::string>()).string();
    const std::string token = entry.at("token");
    job_files::SpecRead read;
    auto current = [&] {  // is this attempt still the job's current one?
      read = job_files::read_spec((fs::path(dir) / job_files::kSpec).string());
      return !read.unreadable && read.token == token;
    };
    if (!current()) {
      // the coordinator has given this job to a newer attempt: this one must not run it
      std::fprintf(stderr, "beverloo worker: %s belongs to a newer attempt; skipped\n", dir.c_str());
      continue;
    }
    if (!read.spec) {
      std::fprintf(stderr, "beverloo worker: %s/%s: %s; skipped\n", dir.c_str(), job_files::kSpec, read.problem.c_str());
      status = exit_code::kConfig;
      continue;
    }
    const job_files::Spec spec = *read.spec;
    const int lock = ::open((fs::path(dir) / job_files::kLock).c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    bool locked = false;
    if (lock >= 0) {
      const std::atomic<std::int64_t> no_step{0};
      HeartbeatWriter waiting(dir, token, spec.heartbeat_s, no_step);  // alive while it waits
      locked = lock_within(lock, kLockWaitSeconds, stop);
    }
    if (!locked || !current()) {
      // another live worker runs this job (a superseded attempt that Slurm has not killed yet)
      std::fprintf(stderr, "beverloo worker: %s is locked by another worker or was given to a newer attempt; skipped\n",
                   dir.c_str());
      if (lock >= 0) ::close(lock);
      continue;
    }
    int code;
    {
      LogRedirect log(dir);
      if (stop->load()) {
        job_files::write_outcome(dir, {token, spec.attempt_no, exit_code::kInterrupted, std::string(to_string(FailureClass::Interrupted)),
                                       "not started: the array task was stopped before it", {}});
        code = exit_code::kInterrupted;
      } else {
        std::fprintf(stderr, "beverloo worker: attempt %d in Slurm task %s_%s (restart %s)\n", spec.attempt_no,
                     env_or("SLURM_ARRAY_JOB_ID", "?").c_str(), env_or("SLURM_ARRAY_TASK_ID", "?").c_str(),
                     env_or("SLURM_RESTART_COUNT", "0").c_str());
        code = run_attempt(dir, spec, stop);
      }
    }
    ::close(lock);
    if (code == exit_code::kInterrupted) status = exit_code::kInterrupted;
    else if (code != exit_code::kOk && status == exit_code::kOk) status = code;
  }
  return status;
}

}  // namespace beverloo
