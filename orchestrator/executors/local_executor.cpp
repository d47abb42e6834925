#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "core/failures.h"
#include "core/stop_signal.h"
#include "local_executor.h"
#include "orchestrator/campaign/job_files.h"

namespace beverloo {
namespace fs = std::filesystem;

namespace {
double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

void LocalExecutor::start(const std::vector<ClaimedJob>& jobs) {
  for (const ClaimedJob& job : jobs) {
    const std::string job_dir = (fs::path(dir_) / job.dir).string();
    const std::string lock = (fs::path(job_dir) / job_files::kLock).string();
    const std::string log = (fs::path(job_dir) / job_files::kLog).string();
    const std::string spec = (fs::path(job_dir) / job_files::kSpec).string();
    // The stop signals stay blocked from before the fork until the worker has installed its
    // handlers (install_stop_handlers unblocks them): a stop the coordinator sends to a worker
    // that is still starting (a full disk, a shutdown, a timeout, moments after the claim) is
    // then held pending and delivered to the handler, and the worker checkpoints and reports
    // itself interrupted instead of dying of the signal's default action.
    const sigset_t stop_signals = stop_signal_set();
    sigset_t before;
    ::pthread_sigmask(SIG_BLOCK, &stop_signals, &before);
    const pid_t pid = fork();
    if (pid != 0) ::pthread_sigmask(SIG_SETMASK, &before, nullptr);  // the coordinator's own mask again
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
      // child: lock the job (inherited across exec), log to the job directory, become the worker
      const int fd = ::open(lock.c_str(), O_CREAT | O_RDWR, 0644);
      if (fd < 0 || ::flock(fd, LOCK_EX | LOCK_NB) != 0) _exit(exit_code::kLockBusy);
      const int logfd = ::open(log.c_str(), O_CREAT | O_WRONLY | O_APPEND, 0644);
      if (logfd >= 0) {
        ::dup2(logfd, STDOUT_FILENO);
        ::dup2(logfd, STDERR_FILENO);
        ::close(logfd);
      }
      ::setpgid(0, 0);  // Ctrl-C reaches the coordinator, which stops the workers in order
      // the coordinator blocks SIGCHLD; the worker starts with only the stop signals blocked
      // (a blocked signal stays pending across exec)
      ::sigprocmask(SIG_SETMASK, &stop_signals, nullptr);
      execl("/proc/self/exe", "beverloo", "worker", spec.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    children_.push_back({pid, job.attempt_id, job_dir});
    store_.set_attempt_pid(job.attempt_id, pid);
  }
}

bool LocalExecutor::adopt(const RunningAttempt& a) {
  const std::string job_dir = (fs::path(dir_) / a.dir).string();
  if (!job_files::lock_is_held(job_dir)) return false;
  adopted_.push_back({a.pid, a.attempt_id, job_dir});
  return true;
}

std::vector<WorkerExit> LocalExecutor::reap() {
  std::vector<WorkerExit> out;
  for (;;) {
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) break;
    auto it = std::find_if(children_.begin(), children_.end(), [&](const Child& c) { return c.pid == pid; });
    if (it == children_.end()) continue;
    WorkerExit e;
    e.attempt_id = it->attempt_id;
    e.have_status = true;
    e.signaled = WIFSIGNALED(status);
    e.code = e.signaled ? WTERMSIG(status) : WEXITSTATUS(status);
    out.push_back(e);
    children_.erase(it);
  }
  return out;
}

std::vector<WorkerExit> LocalExecutor::poll() {
  std::vector<WorkerExit> out = reap();
  // adopted workers are not our children: their lock tells when they end, their files how
  for (auto it = adopted_.begin(); it != adopted_.end();) {
    if (job_files::lock_is_held(it->dir)) {
      ++it;
      continue;
    }
    WorkerExit e;
    e.attempt_id = it->attempt_id;
    out.push_back(e);
    it = adopted_.erase(it);
  }
  // attempts.heartbeat_at: when each worker was last seen alive (holding its job's lock)
  if (now_s() - last_heartbeat_ > heartbeat_s_) {
    last_heartbeat_ = now_s();
    for (const std::vector<Child>* list : {&children_, &adopted_})
      for (const Child& c : *list)
        if (job_files::lock_is_held(c.dir)) store_.heartbeat(c.attempt_id);
  }
  return out;
}

/// Sleeps until a worker exits (SIGCHLD, blocked so that it queues) or 100 ms pass, so that a
/// finished job is ingested and the next one started at once rather than on a polling tick.
void LocalExecutor::wait() {
  sigset_t chld;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  const timespec timeout{0, 100'000'000};
  sigtimedwait(&chld, nullptr, &timeout);
}

void LocalExecutor::stop(std::int64_t attempt_id) {
  for (const Child& c : children_)
    if (c.attempt_id == attempt_id) ::kill(static_cast<pid_t>(c.pid), SIGTERM);
}

std::vector<WorkerExit> LocalExecutor::stop_all() {
  for (const Child& c : children_) ::kill(static_cast<pid_t>(c.pid), SIGTERM);
  std::vector<WorkerExit> out;
  // A worker checkpoints at the end of its current step; one that does not stop within the
  // grace period is stuck, and SIGKILL ends it (its job resumes from the last checkpoint).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kStopGraceSeconds);
  bool killed = false;
  while (!children_.empty()) {
    for (const WorkerExit& e : reap()) out.push_back(e);
    if (!killed && std::chrono::steady_clock::now() > deadline) {
      for (const Child& c : children_) ::kill(static_cast<pid_t>(c.pid), SIGKILL);
      killed = true;
    }
    if (!children_.empty()) ::usleep(20000);
  }
  return out;
}

}  // namespace beverloo
