// The authors' reinjection rule (reinjection.rule = "lanes", docs/authors-model.md section 3):
// fixed lanes taken in turn, one small diameter above the lane's top, the lane's velocity
// reduced by free fall when drag is weak, a sideways kick; lifted where the spot is taken.
#include <gtest/gtest.h>

#include "engine/protocol/hopper_run.h"
#include "engine/protocol/reinjector.h"
#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::small_config;

SimConfig lanes_config() {
  SimConfig c = small_config(2, 8, 4.0, 0.0, 1.0);
  c.W = 20;
  c.reinjection.rule = "lanes";
  c.resolve_and_validate();
  return c;
}

/// n particles of the small species far apart on the floor of the container, at rest.
ParticleState<2> sparse_state(const SimConfig& c, int n) {
  ParticleState<2> s;
  s.sp = Species::bidisperse(2, c.size_ratio);
  s.resize(n);
  for (int k = 0; k < n; ++k) {
    s.inv_mass[k] = 1 / s.mass(k);
    s.x[k] = Vec<2>(-9 + 2.5 * k, 0.6);  // parked below the lanes' tops set by each test
  }
  return s;
}

TEST(LaneReinjection, LanesAreTakenInTurnAlternatingAboutTheAxis) {
  const SimConfig c = lanes_config();
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = sparse_state(c, 1);
  Reinjector<2> r(h, c.reinjection, s.size());
  const double small = s.sp.sigma[0];
  ASSERT_EQ(r.lanes(s), static_cast<int>(std::floor(20 / (2 * small))) - 2);  // the code's floor(L/2) - 2
  // the code's offsets: 0, -2, +2, -4, +4, ... small diameters; after the last lane, lane 0 again
  const double expected[] = {0, -2, 2, -4, 4, -6};
  for (int k = 0; k < 6; ++k) {
    s.exited[0] = 1;
    r.reinject_in_lane(s, 0, k, 0.0);
    EXPECT_NEAR(s.x[0][0], expected[k] * small, 1e-12) << "placement " << k;
    EXPECT_EQ(s.exited[0], 0);
  }
  r.reinject_in_lane(s, 0, r.lanes(s), 0.0);
  EXPECT_NEAR(s.x[0][0], 0.0, 1e-12) << "the counter wraps round the lanes";
}

TEST(LaneReinjection, DropsOneSmallDiameterAboveTheLaneTopWithTheLanesVelocity) {
  const SimConfig c = lanes_config();
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = sparse_state(c, 4);
  const double small = s.sp.sigma[0];
  // lane 0 (x = 0): particle 1 (large) on top at height 6 moving down at 2, particle 2 below it;
  // particle 3 just outside the lane's window (1.5 small diameters), higher: not the lane's top
  s.species[1] = 1;
  s.inv_mass[1] = 1 / s.mass(1);
  s.x[1] = Vec<2>(0.3, 6.0);
  s.v[1] = Vec<2>(0.5, -2.0);
  s.x[2] = Vec<2>(-0.2, 4.0);
  s.v[2] = Vec<2>(0, -1.0);
  s.x[3] = Vec<2>(1.5 * small + 0.01, 9.0);
  Reinjector<2> r(h, c.reinjection, s.size());
  s.exited[0] = 1;
  EXPECT_TRUE(r.reinject_in_lane(s, 0, 0, 0.0)) << "a free spot: not lifted";
  EXPECT_NEAR(s.x[0][1], 6.0 + 0.5 * s.sigma(1) + small, 1e-12);
  // weak drag: the lane's speed less free fall over 1.5 small diameters (g = 1)
  EXPECT_NEAR(-s.v[0][1], std::sqrt(4.0 - 2 * 1.5 * small), 1e-12);
  EXPECT_NEAR(s.v[0][0], 0.1 * 2.0, 1e-12) << "the sideways kick, + for an even index";
  // strong drag (above 0.098 per t0): the lane's speed itself; the kick's sign follows the index
  s.x[3] = Vec<2>(-30, -30);  // out of the way
  std::swap(s.x[0], s.x[3]);
  s.exited[3] = 1;
  r.reinject_in_lane(s, 3, 0, 1.0);
  EXPECT_NEAR(-s.v[3][1], 2.0, 1e-12);
  EXPECT_NEAR(s.v[3][0], -0.2, 1e-12);
}

TEST(LaneReinjection, AnOccupiedSpotIsLiftedUntilItOverlapsNothing) {
  // Sphere neighbours outside a lane's window cannot reach its drop spot (1.5 small diameters
  // exceed any two radii); what can is a DP polygon stretched beyond its body disk, the extra
  // test. Here it refuses every spot below height 6.
  const SimConfig c = lanes_config();
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = sparse_state(c, 2);
  const double small = s.sp.sigma[0];
  s.x[1] = Vec<2>(0, 3.0);  // the lane's top
  Reinjector<2> r(h, c.reinjection, s.size());
  r.set_extra_test([](int, const Vec<2>& p) { return p[1] >= 6.0; });
  s.exited[0] = 1;
  EXPECT_FALSE(r.reinject_in_lane(s, 0, 0, 0.0)) << "lifted";
  EXPECT_TRUE(r.is_free(s, 0, s.x[0], -1));
  EXPECT_GE(s.x[0][1], 6.0);
  EXPECT_LT(s.x[0][1], 6.0 + 0.5 * s.sigma(0)) << "lifted in half-diameter steps, no further";
  EXPECT_GT(s.x[0][1], 3.0 + 0.5 * s.sigma(1) + small);
}

TEST(LaneReinjection, AFlowWithTheLanesRuleKeepsNAndIsDeterministic) {
  SimConfig c = small_config(2, 300, 5, 0.5, 0);
  c.W = 16;
  c.reinjection.rule = "lanes";
  c.reinjection.drop_depth_diameters = 2.5;
  c.resolve_and_validate();
  auto flow = [&] {
    HopperRun<2> run(c, RunOptions{});
    run.prepare();
    run.advance(20000);
    return std::make_pair(run.record(), run.state().x);
  };
  const auto [rec, x] = flow();
  EXPECT_GT(rec.reinjections, 20) << "the test needs reinjections";
  EXPECT_LT(rec.max_overlap_seen, 0.5) << "no placement into an occupied spot";
  EXPECT_EQ(static_cast<int>(x.size()), c.N);
  const auto [rec2, x2] = flow();
  EXPECT_EQ(rec2.reinjections, rec.reinjections);
  for (int k = 0; k < c.N; ++k) EXPECT_EQ(x2[k], x[k]) << "bit for bit, particle " << k;
}

TEST(LaneReinjection, TheRuleIsCheckedAndLeavesDefaultJobsUnchanged) {
  using nlohmann::json;
  const json base = {{"w", 6}, {"zeta", 0.0}, {"mu", 8.5}};
  EXPECT_FALSE(SimConfig::from_json(base).to_json().contains("reinjection") &&
               SimConfig::from_json(base).to_json()["reinjection"].contains("rule"));
  json j = base;
  j["reinjection"] = {{"rule", "lanes"}};
  EXPECT_EQ(SimConfig::from_json(j).to_json()["reinjection"]["rule"], "lanes");
  EXPECT_NE(SimConfig::from_json(j).effective_seed(), SimConfig::from_json(base).effective_seed());
  j["reinjection"] = {{"rule", "teleport"}};
  EXPECT_THROW((void)SimConfig::from_json(j), ConfigError);
  j["reinjection"] = {{"rule", "lanes"}};
  j["dimension"] = 3;
  try {
    (void)SimConfig::from_json(j);
    ADD_FAILURE() << "3D lanes accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "reinjection.rule");
  }
}

}  // namespace
}  // namespace beverloo
