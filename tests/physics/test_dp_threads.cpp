// DP jobs on several threads (DpForceField::set_threads): the shape terms by polygon chunks,
// the smooth contact's rows by vertex chunks (force writes logged and replayed in order), the
// walls, gravity, drag and the integrator by vertex chunks. Every count, and a resume with
// another count, must give the same bits as one thread: positions, velocities, forces and the
// reported energies.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "engine/models/authors_dp_set.h"
#include "engine/models/dp_model.h"
#include "engine/protocol/hopper_run.h"
#include "dp_support.h"

namespace beverloo {
namespace {

SimConfig dp_job(const std::string& model) {
  SimConfig c;
  c.model = model;
  c.N = 200;  // 3200 vertices: several chunks of rows, vertices and polygons
  c.W = 20;
  c.w = 5;
  c.zeta = 0;
  c.mu = 8.5052;  // friction: the smooth contact's friction writes go through the logs too
  c.mu_n = 0.0;
  c.drag_rate = 1.0;
  use_authors_dp_set(c);  // thick walls, the corner and edge scales of the authors' code
  c.seed = 11;
  c.gravity = 20;  // the pile forms within the test's few thousand steps
  c.initial_packing_fraction = 0.6;
  c.resolve_and_validate();
  return c;
}

struct DpRun {
  ParticleState<2> verts;
  ForceReport forces;
};

DpRun flow(const std::string& model, int threads, std::int64_t steps, const std::string& dir = "",
           std::int64_t checkpoint_at = -1) {
  const SimConfig c = dp_job(model);
  RunOptions o;
  o.threads = threads;
  o.adapt_threads = false;  // the count given, throughout
  o.output_dir = dir;
  o.resume = !dir.empty() && checkpoint_at < 0;
  HopperRun<2> run(c, o);
  run.prepare();
  DpSystem& dp = static_cast<DpModel&>(run.model()).system();
  EXPECT_GT(dp.verts().size(), 2 * DpForceField::kVerticesPerChunk);
  EXPECT_GT(dp.polygons().polygons(), 2 * DpForceField::kPolygonsPerChunk);
  if (checkpoint_at >= 0) {
    run.advance(checkpoint_at);
    run.save_checkpoint(dir + "/checkpoint.h5");
  } else {
    run.advance(steps - run.state().step);
  }
  DpRun r{dp.verts(), {}};
  r.forces = dp.forces().compute(dp.verts());  // the same state: forces and energies again
  return r;
}

void expect_same_bits(const DpRun& a, const DpRun& b) {
  ASSERT_EQ(a.verts.size(), b.verts.size());
  const std::size_t bytes = sizeof(Vec<2>) * a.verts.size();
  EXPECT_EQ(0, std::memcmp(a.verts.x.data(), b.verts.x.data(), bytes)) << "positions differ";
  EXPECT_EQ(0, std::memcmp(a.verts.v.data(), b.verts.v.data(), bytes)) << "velocities differ";
  EXPECT_EQ(0, std::memcmp(a.verts.f.data(), b.verts.f.data(), bytes)) << "forces differ";
  EXPECT_EQ(a.forces.U_contact, b.forces.U_contact);
  EXPECT_EQ(a.forces.U_shape, b.forces.U_shape);
  EXPECT_EQ(a.forces.U_wall, b.forces.U_wall);
  EXPECT_EQ(a.forces.U_gravity, b.forces.U_gravity);
  EXPECT_EQ(a.forces.P_friction, b.forces.P_friction);
  EXPECT_EQ(a.forces.P_drag, b.forces.P_drag);
  EXPECT_EQ(a.forces.max_overlap, b.forces.max_overlap);
}

/// Polygons pressed into one another on a lattice (every contact branch busy), with random
/// velocities (friction): one evaluation with `threads` threads.
DpRun pressed(const std::string& model, int threads) {
  SimConfig c = dp_job(model);
  c.W = 20;
  std::vector<Vec<2>> centres;
  for (int row = 0; row < 14; ++row)
    for (int col = 0; col < 15; ++col) centres.emplace_back(-6.5 + 0.92 * col + 0.46 * (row % 2), 0.5 + 0.85 * row);
  testing::DpFixture fx(c, centres, 0.15, 5);
  Rng rng(9);
  for (auto& v : fx.verts.v) v = Vec<2>(rng.uniform(-1, 1), rng.uniform(-1, 1));
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.set_threads(threads);
  DpRun r{fx.verts, {}};
  r.forces = ff.compute(r.verts);
  return r;
}

TEST(DpThreads, EveryThreadCountGivesTheSameForcesOnAPressedPile) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    const DpRun one = pressed(model, 1);
    EXPECT_GT(one.forces.U_contact, 1.0) << model;
    EXPECT_LT(one.forces.P_friction, 0) << model;
    expect_same_bits(one, pressed(model, 2));
    expect_same_bits(one, pressed(model, 3));
  }
}

TEST(DpThreads, EveryThreadCountGivesTheSameBitsSmooth) {
  const DpRun one = flow("dp_smooth", 1, 3000);
  EXPECT_GT(one.forces.U_contact, 0);  // the first polygons touch
  expect_same_bits(one, flow("dp_smooth", 2, 3000));
  expect_same_bits(one, flow("dp_smooth", 3, 3000));
}

TEST(DpThreads, EveryThreadCountGivesTheSameBitsRough) {
  const DpRun one = flow("dp_rough", 1, 1500);
  expect_same_bits(one, flow("dp_rough", 2, 1500));
}

TEST(DpThreads, ResumedRunContinuesBitForBitWithAnotherThreadCount) {
  const std::string dir = (std::filesystem::temp_directory_path() / "beverloo_dp_threads_resume").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const DpRun straight = flow("dp_smooth", 1, 3000);
  flow("dp_smooth", 2, 0, dir, 1500);                          // checkpoint part-way, two threads
  expect_same_bits(straight, flow("dp_smooth", 1, 3000, dir));  // resumed with one
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace beverloo
