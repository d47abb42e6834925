// The one failure table (core/failures.h): every class has its own name, its exit code maps
// back to it, and the retry policy is the one the store applies; and how a full disk is told.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <set>
#include <string>

#include <csignal>
#include <pthread.h>

#include "core/disk_space.h"
#include "core/stop_signal.h"
#include "core/failures.h"

namespace beverloo {
namespace {

TEST(FailureTable, EveryClassHasOneNameAndItsExitCodeMapsBack) {
  std::set<std::string> names;
  for (int i = 0; i <= static_cast<int>(FailureClass::Stalled); ++i) {
    const auto c = static_cast<FailureClass>(i);
    const FailureInfo& f = failure_info(c);
    EXPECT_EQ(f.cls, c);
    EXPECT_TRUE(names.insert(std::string(f.name)).second) << f.name;
    EXPECT_EQ(failure_from_name(f.name), c);
    if (f.exit_code >= 0) {
      EXPECT_EQ(failure_from_exit(false, f.exit_code), c) << f.name;
    }
  }
  EXPECT_EQ(failure_from_exit(true, 0), FailureClass::Killed);
  EXPECT_EQ(failure_from_exit(false, 99), FailureClass::Internal);
  EXPECT_FALSE(failure_from_name("nonsense").has_value());
}

TEST(FailureTable, SciencePaysFromTheBudgetInfrastructureDoesNot) {
  EXPECT_EQ(failure_info(FailureClass::InvalidParameters).retry, RetryPolicy::Never);
  EXPECT_EQ(failure_info(FailureClass::BlowUp).retry, RetryPolicy::Never);  // deterministic: a retry repeats it
  EXPECT_EQ(failure_info(FailureClass::Io).retry, RetryPolicy::Budgeted);
  for (FailureClass c : {FailureClass::Killed, FailureClass::Lost, FailureClass::Interrupted, FailureClass::Timeout,
                         FailureClass::Preempted, FailureClass::NodeFailure, FailureClass::Stalled, FailureClass::DiskFull})
    EXPECT_TRUE(is_infrastructure(c)) << to_string(c);
  EXPECT_EQ(failure_info(FailureClass::Cancelled).retry, RetryPolicy::Cancel);
  EXPECT_EQ(failure_info(FailureClass::Interrupted).exit_code, exit_code::kInterrupted);
  EXPECT_EQ(failure_info(FailureClass::Lost).exit_code, exit_code::kLockBusy);
}

TEST(DiskSpace, AFullDiskIsToldByItsMessageOrItsFreeSpace) {
  EXPECT_TRUE(no_space_left("/tmp", std::string("cannot write checkpoint.h5.tmp: ") + std::strerror(ENOSPC)));
  EXPECT_TRUE(no_space_left("/tmp", "database or disk is full"));
  // a file system with room: an I/O failure there is not for want of room
  EXPECT_FALSE(no_space_left("/tmp", "permission denied"));
  // a directory that could not be made: its nearest existing parent's file system is asked
  EXPECT_FALSE(no_space_left("/tmp/beverloo-no-such-dir/jobs/abc", "cannot create directory"));
}

// A local worker starts with the stop signals blocked (local_executor.cpp): a stop sent before
// its handlers are in place waits, and reaches the handler when install_stop_handlers() unblocks
// it, instead of killing the worker (a worker stopped moments after its claim died of SIGTERM
// and was recorded "killed": integration.full_disk failed so under load).
TEST(StopSignal, AStopSentWhileBlockedReachesTheHandlerOnceInstalled) {
  const sigset_t set = stop_signal_set();
  sigset_t before;
  ASSERT_EQ(pthread_sigmask(SIG_BLOCK, &set, &before), 0);
  ASSERT_EQ(pthread_kill(pthread_self(), SIGTERM), 0);  // blocked: held pending, not fatal
  sigset_t pending;
  sigpending(&pending);
  EXPECT_TRUE(sigismember(&pending, SIGTERM));
  const std::atomic<bool>* stop = install_stop_handlers();
  EXPECT_TRUE(stop->load()) << "the pending stop was delivered to the handler when unblocked";
  sigset_t now;
  pthread_sigmask(SIG_SETMASK, nullptr, &now);
  EXPECT_FALSE(sigismember(&now, SIGTERM));
  EXPECT_FALSE(sigismember(&now, SIGINT));
  EXPECT_FALSE(sigismember(&now, SIGUSR1));
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
}

TEST(DiskSpace, AFileSystemWithRoomIsNotFull) {
  EXPECT_FALSE(file_system_full("/tmp"));
  EXPECT_FALSE(file_system_full("/tmp/beverloo-no-such-dir/jobs/abc"));  // its nearest existing parent
}

}  // namespace
}  // namespace beverloo
