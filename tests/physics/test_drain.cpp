// The draining hopper (reinject = false, physics.md 9): exited particles leave the simulation,
// the run ends when the hopper has drained, N(t) follows dN/dt = -c0 sqrt(N) on its steady part,
// and the same job gives the same result; SP in a 45/0 hopper and DP polygons alike.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "engine/protocol/hopper_run.h"
#include "support.h"

namespace beverloo {
namespace {

SimConfig drain_config() {
  SimConfig c;
  c.dimension = 2;
  c.N = 400;
  c.W = 36;
  c.w = 4;
  c.theta_w_left_deg = 45;
  c.theta_w_right_deg = 0;  // the experiments' 45/0 hopper
  c.E_sp = 100;
  c.zeta = 0.316;
  c.mu = 0;
  c.reinject = false;
  c.seed = 3;
  c.run.t_max = 1000;
  c.resolve_and_validate();
  return c;
}

TEST(Drain, EveryParticleLeavesOnceAndTheRunEndsDrained) {
  const SimConfig c = drain_config();
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const RunResult r = run.run();
  EXPECT_EQ(r.status, "drained") << r.stop_reason;
  EXPECT_TRUE(r.draining);
  EXPECT_EQ(r.n_initial, 400);
  EXPECT_EQ(r.n_remaining, 0);
  EXPECT_EQ(r.exits_total, 400);
  // every exit is one particle's one exit: exit times increase, and at the end the simulation
  // holds only particles that have exited but not yet fallen out of it
  for (std::size_t k = 1; k < r.exit_time.size(); ++k) EXPECT_GE(r.exit_time[k], r.exit_time[k - 1]);
  EXPECT_LT(run.state().size(), 400);
  for (int i = 0; i < run.state().size(); ++i) EXPECT_TRUE(run.state().exited[i]);
  // the fit: c0 > 0 with a finite error; Q is c0; the window spans its blocks
  ASSERT_TRUE(r.drain.ok) << r.drain.message;
  EXPECT_DOUBLE_EQ(r.Q, r.drain.c0);
  EXPECT_GT(r.Q, 0);
  EXPECT_LT(r.Q_err / r.Q, 0.2);
  EXPECT_GT(r.drain.blocks, 10);
  // dN/dt = -c0 sqrt(N): sqrt(N) falls linearly in time; between N = 300 and N = 100 the
  // measured time agrees with 2 (sqrt 300 - sqrt 100) / c0 within 15 %
  const double t300 = r.exit_time[99], t100 = r.exit_time[299];
  EXPECT_NEAR((t100 - t300) * r.Q / (2 * (std::sqrt(300.0) - std::sqrt(100.0))), 1.0, 0.15);
}

TEST(Drain, SameJobGivesTheSameExitsAndStopBelowEndsEarlier) {
  SimConfig c = drain_config();
  c.N = 300;
  c.resolve_and_validate();
  const RunResult a = run_hopper(c, RunOptions{}), b = run_hopper(c, RunOptions{});
  EXPECT_EQ(a.exit_time, b.exit_time);
  EXPECT_EQ(a.Q, b.Q);
  // stop_below does not enter the seed: the same drain, cut where 150 remain
  c.drain.stop_below = 150;
  c.resolve_and_validate();
  const RunResult cut = run_hopper(c, RunOptions{});
  EXPECT_EQ(cut.status, "drained");
  EXPECT_EQ(cut.n_remaining, 150);
  ASSERT_EQ(cut.exit_time.size(), 150u);
  for (int k = 0; k < 150; ++k) EXPECT_EQ(cut.exit_time[k], a.exit_time[k]);
}

// A flat floor (theta_w = 90) keeps particles in its corners that never leave: the flow stops
// with nothing over the opening. That is a dead zone, not a clog: the run ends drained with Q
// the fit's c0 over its steady exits (the experiments fit their flat-bottomed hoppers the same
// way). An arch over a narrow orifice with friction is a clog: Q = 0, as before.
TEST(Drain, AFlatFloorsDeadZoneEndsDrainedAnArchOverTheOrificeClogged) {
  SimConfig c;
  c.dimension = 2;
  c.N = 400;
  c.W = 30;
  c.w = 5;
  c.theta_w_left_deg = c.theta_w_right_deg = 90;
  c.zeta = 0.316;
  c.mu = 0;
  c.reinject = false;
  c.run.t_clog = 20;
  c.drain.fit_skip = 50;
  c.resolve_and_validate();
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const RunResult r = run.run();
  EXPECT_EQ(r.status, "drained") << r.stop_reason;
  EXPECT_FALSE(r.clogged);
  ASSERT_GT(r.n_remaining, 0) << "a flat floor of 30 keeps some particles in its corners";
  EXPECT_EQ(run.state().size(), r.n_remaining);
  for (int i = 0; i < run.state().size(); ++i)  // each rests beside the opening, on the floor
    EXPECT_GE(std::fabs(run.state().x[i][0]), c.w / 2) << "particle " << i;
  EXPECT_NE(r.stop_reason.find("none over the orifice"), std::string::npos) << r.stop_reason;
  ASSERT_TRUE(r.drain.ok) << r.drain.message;
  EXPECT_DOUBLE_EQ(r.Q, r.drain.c0);
  EXPECT_GT(r.Q, 0);

  SimConfig f = c;  // friction only, the orifice two diameters wide: an arch forms early
  f.w = 2.5;
  f.zeta = 0;
  f.mu = 31.6;
  f.resolve_and_validate();
  HopperRun<2> arch(f, RunOptions{});
  arch.prepare();
  const RunResult a = arch.run();
  EXPECT_EQ(a.status, "clogged") << a.stop_reason;
  EXPECT_EQ(a.Q, 0);
  int over = 0;
  for (int i = 0; i < arch.state().size(); ++i)
    over += arch.state().x[i][1] > 0 && std::fabs(arch.state().x[i][0]) < f.w / 2;
  EXPECT_GT(over, 0) << "a clog holds a particle over the opening";
}

TEST(Drain, DeformablePolygonsDrainTheSameWay) {
  SimConfig c;
  c.model = "dp_smooth";
  c.N = 40;
  c.W = 12;
  c.w = 3;
  c.theta_w_left_deg = c.theta_w_right_deg = 45;
  c.E_w = 100;
  c.dp.E_c = 115.7;  // the authors' contact: a time step that keeps this test short
  c.dp.contact_width = 0.2;
  c.zeta = 0.316;
  c.mu = 0;
  c.reinject = false;
  c.drain.fit_skip = 3;
  c.drain.block_exits = 4;
  c.seed = 4;
  c.run.t_max = 200;
  c.resolve_and_validate();
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const RunResult r = run.run();
  EXPECT_EQ(r.status, "drained") << r.stop_reason;
  EXPECT_EQ(r.exits_total, 40);
  ASSERT_TRUE(r.drain.ok) << r.drain.message;
  EXPECT_GT(r.Q, 0);
  // the removed polygons took their vertices with them
  EXPECT_EQ(run.dp()->verts().size(), run.state().size() * c.dp.n_v);
  EXPECT_EQ(run.dp()->polygons().polygons(), run.state().size());
}

TEST(Drain, ConfigurationsThatCannotBeFittedOrBuiltAreRefused) {
  SimConfig c = drain_config();
  c.N = 60;  // 100 left out at each end: nothing steady
  EXPECT_THROW(c.resolve_and_validate(), ConfigError);
  try {
    c.resolve_and_validate();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("drain.fit_skip"), std::string::npos) << e.what();
  }
  SimConfig v = drain_config();
  v.theta_w_left_deg = v.theta_w_right_deg = 0;
  EXPECT_THROW(v.resolve_and_validate(), ConfigError);
  SimConfig t = drain_config();
  t.run.trajectory_every_steps = 100;
  EXPECT_THROW(t.resolve_and_validate(), ConfigError);
}

}  // namespace
}  // namespace beverloo
