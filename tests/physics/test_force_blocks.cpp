// The SP force evaluation in blocks (neighbor_list.h: blocks; force_field.h: evaluate): the
// forces equal a brute-force sum over all pairs, whatever the blocks; every thread count gives
// the same bits; a run resumed from a checkpoint (which holds the list and the particle order)
// continues bit for bit. The systems here are large enough for two blocks or more.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "engine/forces/kinetic_friction.h"
#include "engine/io/h5.h"
#include "engine/protocol/hopper_run.h"
#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::random_state;
using testing::random_velocities;
using testing::small_config;

/// Every force by the definitions (physics.md 3), over all pairs i < j: no list, no blocks.
template <int D>
VecArray<D> brute_force(const SimConfig& c, const Hopper<D>& h, const ParticleState<D>& s) {
  VecArray<D> f(s.size(), Vec<D>::Zero());
  const FrictionLaw law{c.mu_normal(), c.mu_tangential()};
  for (int i = 0; i < s.size(); ++i) {
    const double ci = c.zeta + c.drag_rate * s.mass(i);
    f[i] -= ci * s.v[i];
    f[i][kUp<D>] -= s.mass(i) * c.gravity;
    const double half = 0.5 * s.sigma(i);
    for (int w = 0; w < Hopper<D>::kNumWalls; ++w) {
      const Vec<D> away = s.x[i] - h.nearest_point(w, s.x[i]);
      const double d = away.norm();
      if (d < half && d > 0) f[i] += (c.E_w * (1 - d / half) / half / d) * away;
    }
    for (int j = i + 1; j < s.size(); ++j) {
      const double sig = 0.5 * (s.sigma(i) + s.sigma(j));
      const Vec<D> dx = s.x[i] - s.x[j];
      const double r = dx.norm();
      if (r >= sig) continue;
      Vec<D> fij = (c.E_sp * (1 - r / sig) / sig / r) * dx;
      fij += law.split() ? kinetic_friction_force<D>(law, s.v[i], s.v[j], Vec<D>(dx / r))
                         : kinetic_friction_force<D>(law.mu_t, s.v[i], s.v[j]);
      f[i] += fij;
      f[j] -= fij;
    }
  }
  return f;
}

template <int D>
void check_blocks_against_brute_force(int n, double mu, double mu_n, double zeta) {
  SimConfig c = small_config(D, n, 3.0, zeta, mu);
  c.W = D == 2 ? 40 : 14;
  c.gravity = 1;
  if (mu_n >= 0) c.mu_n = mu_n;
  c.resolve_and_validate();
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, 5);
  random_velocities<D>(s, 9);
  ForceField<D> ff(c, h);
  ParticleState<D> scratch;
  ff.list().build_sorting(s, h, scratch);  // as the model does: blocks are runs of cells
  ASSERT_GE(ff.list().blocks(), 2) << "too few particles for blocks: the test would test nothing";
  const ForceReport r = ff.evaluate(s);
  const VecArray<D> want = brute_force<D>(c, h, s);
  double largest = 0;
  for (const auto& fi : want) largest = std::max(largest, fi.norm());
  for (int i = 0; i < s.size(); ++i)
    ASSERT_LT((s.f[i] - want[i]).norm(), 1e-12 * largest)
        << "particle " << i << " (block boundary at " << ff.list().block_begin(1) << ")";
  // the energy too: each pair once, whichever block counted it
  double U = 0;
  for (int i = 0; i < s.size(); ++i)
    for (int j = i + 1; j < s.size(); ++j) {
      const double sig = 0.5 * (s.sigma(i) + s.sigma(j)), r = (s.x[i] - s.x[j]).norm();
      if (r < sig) U += 0.5 * c.E_sp * (1 - r / sig) * (1 - r / sig);
    }
  EXPECT_NEAR(r.U_contact, U, 1e-10 * U);
}

TEST(ForceBlocks, EqualBruteForceFullFriction2D) { check_blocks_against_brute_force<2>(1500, 3.0, -1, 0.2); }
TEST(ForceBlocks, EqualBruteForceSplitFriction2D) { check_blocks_against_brute_force<2>(1500, 3.0, 0.0, 0.0); }
TEST(ForceBlocks, EqualBruteForceFullFriction3D) { check_blocks_against_brute_force<3>(2500, 3.0, -1, 0.2); }

/// The 2D pair runs four pairs at a time (sp_pairs_avx2.h, where the processor has AVX2) and
/// two at a time (sp_pairs_sse2.h) give the scalar loop's forces bit for bit, for each friction
/// law (blocks and all); the four and the two at a time the same bits, also of the energy and
/// power sums.
void check_simd_equals_scalar(double mu, double mu_n, double zeta) {
  SimConfig c = small_config(2, 1500, 3.0, zeta, mu);
  c.W = 40;
  c.gravity = 1;
  if (mu_n >= 0) c.mu_n = mu_n;
  c.resolve_and_validate();
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 5);
  random_velocities<2>(s, 9);
  ForceField<2> ff(c, h);
  ParticleState<2> scratch;
  ff.list().build_sorting(s, h, scratch);
  ASSERT_GE(ff.list().blocks(), 2);
  SpContact<2>& contact = const_cast<SpContact<2>&>(ff.contact());
  const bool four = contact.set_simd_width(4) == 4;
  const ForceReport four_report = ff.evaluate(s);
  const VecArray<2> by_four = s.f;
  ASSERT_EQ(contact.set_simd_width(2), 2);
  const ForceReport two_report = ff.evaluate(s);
  const VecArray<2> by_two = s.f;
  ASSERT_EQ(contact.set_simd_width(1), 1);
  const ForceReport scalar_report = ff.evaluate(s);
  int touching = 0;
  for (int i = 0; i < s.size(); ++i)
    for (int d = 0; d < 2; ++d) {
      // equal values (a lane whose pair misses adds +-0, which the scalar loop skips: -0 may become +0)
      ASSERT_EQ(by_two[i][d], s.f[i][d]) << "two at a time, particle " << i;
      // the same bits, zeros' signs and all
      ASSERT_EQ(std::memcmp(&by_four[i][d], &by_two[i][d], sizeof(double)), 0) << "four at a time, particle " << i;
    }
  EXPECT_EQ(std::memcmp(&four_report.U_contact, &two_report.U_contact, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&four_report.P_friction, &two_report.P_friction, sizeof(double)), 0);
  EXPECT_EQ(four_report.max_overlap, two_report.max_overlap);
  for (int i = 0; i < s.size(); ++i)
    for (const int* p = ff.list().row_begin(i); p != ff.list().row_end(i); ++p)
      touching += (s.x[i] - s.x[*p]).norm() < 0.5 * (s.sigma(i) + s.sigma(*p));
  EXPECT_GT(touching, 500) << "too few contacts for the comparison to mean anything";
  EXPECT_GT(scalar_report.U_contact, 0);
  if (mu > 0) {
    EXPECT_LT(scalar_report.P_friction, 0);
  }
  if (!four) std::printf("no AVX2 here: four at a time fell back to two\n");
}

TEST(ForceBlocks, TwoPairsAtATimeEqualTheScalarLoopNoFriction) { check_simd_equals_scalar(0, -1, 0.3); }
TEST(ForceBlocks, TwoPairsAtATimeEqualTheScalarLoopFullFriction) { check_simd_equals_scalar(3.0, -1, 0); }
TEST(ForceBlocks, TwoPairsAtATimeEqualTheScalarLoopSplitFriction) { check_simd_equals_scalar(3.0, 0.0, 0); }

/// A flowing hopper large enough for blocks, advanced `steps` steps with `threads` threads.
template <int D>
ParticleState<D> flow(int threads, std::int64_t steps, const std::string& dir = "", std::int64_t checkpoint_at = -1) {
  SimConfig c;
  c.dimension = D;
  c.N = D == 2 ? 1200 : 2000;
  c.W = D == 2 ? 30 : 14;
  c.w = 5;
  c.zeta = 0.3;
  c.mu = 2.0;
  c.seed = 3;
  c.resolve_and_validate();
  RunOptions o;
  o.threads = threads;
  o.output_dir = dir;
  o.resume = !dir.empty() && checkpoint_at < 0;
  HopperRun<D> run(c, o);
  run.prepare();
  EXPECT_GE(NeighborList<D>::block_count(c.N), 2);
  if (checkpoint_at >= 0) {
    run.advance(checkpoint_at);
    run.save_checkpoint(dir + "/checkpoint.h5");
    return run.state();
  }
  run.advance(steps - run.state().step);
  return run.state();
}

template <int D>
void expect_same_bits(const ParticleState<D>& a, const ParticleState<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.x.data(), b.x.data(), sizeof(Vec<D>) * a.size())) << "positions differ";
  EXPECT_EQ(0, std::memcmp(a.v.data(), b.v.data(), sizeof(Vec<D>) * a.size())) << "velocities differ";
  EXPECT_EQ(0, std::memcmp(a.f.data(), b.f.data(), sizeof(Vec<D>) * a.size())) << "forces differ";
  EXPECT_EQ(a.id, b.id);
}

TEST(ForceBlocks, EveryThreadCountGivesTheSameBits2D) {
  const ParticleState<2> one = flow<2>(1, 4000);
  expect_same_bits(one, flow<2>(2, 4000));
  expect_same_bits(one, flow<2>(3, 4000));
}

TEST(ForceBlocks, EveryThreadCountGivesTheSameBits3D) {
  const ParticleState<3> one = flow<3>(1, 1500);
  expect_same_bits(one, flow<3>(2, 1500));
}

TEST(ForceBlocks, ResumedRunContinuesBitForBitWithAnotherThreadCount) {
  const std::string dir = (std::filesystem::temp_directory_path() / "beverloo_blocks_resume").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const ParticleState<2> straight = flow<2>(1, 4000);
  flow<2>(2, 0, dir, 2500);                           // checkpoint part-way, two threads
  expect_same_bits(straight, flow<2>(1, 4000, dir));  // resumed with one
  std::filesystem::remove_all(dir);
}

TEST(ForceBlocks, CheckpointOfAnotherEngineIsSetAsideAndTheRunStartsOver) {
  // a checkpoint of another engine version continues neither engine's run: set aside, start over
  const std::string dir = (std::filesystem::temp_directory_path() / "beverloo_other_engine").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  flow<2>(1, 0, dir, 300);
  {
    H5Handle f = h5::open_file(dir + "/checkpoint.h5", true);
    H5Adelete(f, "engine_version");
    h5::attr(f, "engine_version", std::string("0.0.1"));
  }
  expect_same_bits(flow<2>(1, 600), flow<2>(1, 600, dir));  // started over: a fresh run's bits
  EXPECT_TRUE(std::filesystem::exists(dir + "/checkpoint.h5.unusable"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace beverloo
