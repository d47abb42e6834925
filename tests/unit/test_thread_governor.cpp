// The thread governor (engine/protocol/thread_governor.h) keeps the faster thread count: fed
// window times of a node where one count is faster, it settles on that one, probes the other
// ever less often while the choice holds, and follows a change of load.
#include "engine/protocol/thread_governor.h"

#include <gtest/gtest.h>

namespace beverloo {
namespace {

/// Runs n windows with the given seconds per window on 1 and on T threads; returns how many of
/// them ran on 1 thread.
int run_windows(ThreadGovernor& g, int n, double one, double many) {
  int on_one = 0;
  for (int k = 0; k < n; ++k) {
    const bool single = g.threads() == 1;
    on_one += single;
    g.end_window(single ? one : many);
  }
  return on_one;
}

TEST(ThreadGovernor, OneThreadAsksNothing) {
  ThreadGovernor g(1);
  EXPECT_FALSE(g.active());
  EXPECT_EQ(g.threads(), 1);
}

TEST(ThreadGovernor, KeepsTheRequestedCountWhereItIsFaster) {
  ThreadGovernor g(2);
  EXPECT_EQ(g.threads(), 2);
  const int on_one = run_windows(g, 400, 1.0, 0.6);  // an idle node: 2 threads are faster
  EXPECT_EQ(g.threads(), 2);
  EXPECT_LT(on_one, 400 / 20) << "probes of the slower count must become rare";
}

TEST(ThreadGovernor, FallsBackToOneThreadOnALoadedNodeAndFollowsTheLoad) {
  ThreadGovernor g(2);
  int on_one = run_windows(g, 400, 1.0, 2.5);  // the other core busy: 2 threads wait at barriers
  EXPECT_EQ(g.threads(), 1);
  EXPECT_GT(on_one, 400 - 400 / 20);
  // the load goes away: within the longest probe interval it uses 2 threads again
  on_one = run_windows(g, 2 * ThreadGovernor::kProbeEveryMost + 2, 1.0, 0.6);
  EXPECT_EQ(g.threads(), 2);
  EXPECT_LT(on_one, 2 * ThreadGovernor::kProbeEveryMost + 2);
}

}  // namespace
}  // namespace beverloo
