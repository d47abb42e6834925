#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "executor.h"
#include "job_files.h"

namespace beverloo {
namespace fs = std::filesystem;

std::int64_t LocalExecutor::start(const ClaimedJob& job, const std::string& job_dir) {
  const std::string lock = (fs::path(job_dir) / job_files::kLock).string();
  const std::string log = (fs::path(job_dir) / job_files::kLog).string();
  const std::string spec = (fs::path(job_dir) / job_files::kSpec).string();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    // child: lock the job (inherited across exec), log to the job directory, become the worker
    const int fd = ::open(lock.c_str(), O_CREAT | O_RDWR, 0644);
    if (fd < 0 || ::flock(fd, LOCK_EX | LOCK_NB) != 0) _exit(job_files::kLockBusyExit);
    const int logfd = ::open(log.c_str(), O_CREAT | O_WRONLY | O_APPEND, 0644);
    if (logfd >= 0) {
      ::dup2(logfd, STDOUT_FILENO);
      ::dup2(logfd, STDERR_FILENO);
      ::close(logfd);
    }
    ::setpgid(0, 0);  // Ctrl-C reaches the coordinator, which stops the workers in order
    sigset_t none;    // the coordinator blocks SIGCHLD; the worker starts with a clean mask
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    execl("/proc/self/exe", "beverloo", "worker", spec.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  children_.push_back({pid, job.attempt_id});
  return pid;
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
    e.signaled = WIFSIGNALED(status);
    e.code = e.signaled ? WTERMSIG(status) : WEXITSTATUS(status);
    out.push_back(e);
    children_.erase(it);
  }
  return out;
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
