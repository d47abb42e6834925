// The stopping rules of a continuous flow: run.stop_unreachable ends a run whose error cannot
// reach the target within t_max (status "unreachable", Q with its error) and changes nothing
// else: without it the same job runs to t_max, and with a reachable target it converges as before.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/protocol/hopper_run.h"
#include "support.h"

namespace beverloo {
namespace {

SimConfig small_flow(double target, bool stop_unreachable) {
  SimConfig c = testing::small_config(2, 150, 4, 0.316, 0);  // drag only, W = 12
  c.run.t_max = 60;
  c.run.min_transient = 3;
  c.run.min_window = 8;
  c.run.rate_bin = 0.5;
  c.run.check_interval = 2;
  c.run.target_rel_err = target;
  c.run.stop_unreachable = stop_unreachable;
  c.resolve_and_validate();
  return c;
}

RunResult run_job(const SimConfig& c) {
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  return run.run();
}

TEST(StoppingRules, AnUnreachableTargetStopsEarlyWithItsErrorAndOnlyWhenAsked) {
  // SE(Q)/Q of 0.1 % in 60 t0 of a 150-particle flow is out of reach (a few % after 10 t0)
  const RunResult stopped = run_job(small_flow(0.001, true));
  EXPECT_EQ(stopped.status, "unreachable") << stopped.stop_reason;
  EXPECT_LT(stopped.window_end, 40.0) << "it should stop soon after the first window, not near t_max";
  EXPECT_GT(stopped.Q, 0);
  EXPECT_GT(stopped.Q_err, 0);
  // the prediction it acted on: the error falls as 1/sqrt(window) and would still miss the target
  const double window = stopped.window_end - stopped.window_start;
  const double predicted = stopped.Q_rel_err * std::sqrt(window / (60.0 - stopped.window_start));
  EXPECT_GT(predicted, HopperRun<2>::kUnreachableMargin * 0.001);

  const RunResult full = run_job(small_flow(0.001, false));
  EXPECT_EQ(full.status, "time_limit");
  EXPECT_GT(full.window_end, 55.0);
  EXPECT_LT(full.Q_rel_err, stopped.Q_rel_err) << "the longer window has the smaller error";

  // a reachable target: the rule never fires, and the result is the run without it, bit for bit
  const RunResult a = run_job(small_flow(0.2, true));
  const RunResult b = run_job(small_flow(0.2, false));
  EXPECT_EQ(a.status, "converged");
  EXPECT_EQ(a.Q, b.Q);
  EXPECT_EQ(a.Q_err, b.Q_err);
  EXPECT_EQ(a.window_end, b.window_end);
  // off is the default and leaves the canonical job (and so every job key made before it) as it was
  EXPECT_FALSE(small_flow(0.2, false).to_json()["run"].contains("stop_unreachable"));
  EXPECT_TRUE(small_flow(0.2, true).to_json()["run"].value("stop_unreachable", false));
}

}  // namespace
}  // namespace beverloo
