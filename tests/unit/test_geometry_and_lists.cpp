// Hopper walls (nearest points, corners, containment) and the Verlet list against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::random_state;
using testing::small_config;

TEST(Hopper2D, FunnelWallsMeetSideWallsAtTheStatedHeight) {
  const Hopper<2> h(50, 6, units::deg_to_rad(60), units::deg_to_rad(30));
  // (W - w)/2 cot(theta): 22 cot 60 = 12.70, 22 cot 30 = 38.11
  EXPECT_NEAR(h.nearest_point(2, Vec<2>(-30, -100))[1], 22 / std::tan(units::deg_to_rad(60)), 1e-12);
  EXPECT_NEAR(h.nearest_point(3, Vec<2>(30, -100))[1], 22 / std::tan(units::deg_to_rad(30)), 1e-12);
  EXPECT_NEAR(h.funnel_top(), 22 / std::tan(units::deg_to_rad(30)), 1e-12);
  // flat bottom: the funnel walls are at height 0
  const Hopper<2> flat(50, 6, units::deg_to_rad(90), units::deg_to_rad(90));
  EXPECT_DOUBLE_EQ(flat.funnel_top(), 0);
  EXPECT_EQ(flat.nearest_point(0, Vec<2>(-10, 2)), Vec<2>(-10, 0));
}

TEST(Hopper2D, OrificeEdgesAreCorners) {
  const Hopper<2> h(50, 6, units::pi / 2, units::pi / 2);
  // inside the orifice, the nearest point of each funnel wall is its end point
  EXPECT_EQ(h.nearest_point(0, Vec<2>(-2.8, 0.1)), Vec<2>(-3, 0));
  EXPECT_EQ(h.nearest_point(1, Vec<2>(2.9, -0.2)), Vec<2>(3, 0));
  EXPECT_TRUE(h.contains(Vec<2>(0, 5)));
  EXPECT_TRUE(h.contains(Vec<2>(10, -1)));  // below the plane: judged when it crosses
  EXPECT_TRUE(h.contains(Vec<2>(26, -1)));  // and no side walls there: flung out sideways
  EXPECT_FALSE(h.contains(Vec<2>(26, 5)));
  const Hopper<2> funnel(50, 6, units::deg_to_rad(45), units::deg_to_rad(45));
  EXPECT_TRUE(funnel.contains(Vec<2>(3.5, 1)));
  EXPECT_FALSE(funnel.contains(Vec<2>(4.5, 1)));  // outside the 45 degree wall
}

TEST(Hopper2D, AVerticalWallPutsTheOrificeInTheContainersCorner) {
  // 45/0 (the experiments' second hopper): W = 50, w = 6; the right wall rises straight from the
  // orifice's right edge, the left wall spans W - w = 44 at 45 degrees up to height 44
  const Hopper<2> h(50, 6, units::deg_to_rad(45), 0);
  EXPECT_DOUBLE_EQ(h.x_min(), -47);
  EXPECT_DOUBLE_EQ(h.x_max(), 3);
  EXPECT_DOUBLE_EQ(h.lateral_centre(), -22);
  EXPECT_DOUBLE_EQ(h.half_width(), 25);
  EXPECT_NEAR(h.funnel_top(), 44, 1e-12);
  EXPECT_TRUE(h.has_wall(0) && h.has_wall(1) && h.has_wall(2));
  EXPECT_FALSE(h.has_wall(3));  // the vertical funnel wall is the right side
  // the vertical wall: nearest point level with p, its lower end the orifice corner
  EXPECT_EQ(h.nearest_point(1, Vec<2>(2.5, 30)), Vec<2>(3, 30));
  EXPECT_EQ(h.nearest_point(1, Vec<2>(2.5, -0.5)), Vec<2>(3, 0));
  // the absent wall is far beyond any contact, with a finite distance
  const double d2 = (Vec<2>(2.5, 30) - h.nearest_point(3, Vec<2>(2.5, 30))).squaredNorm();
  EXPECT_GT(d2, 1e290);
  EXPECT_TRUE(std::isfinite(d2));
  // the slanted wall ends on the left side at height 44
  EXPECT_NEAR(h.nearest_point(2, Vec<2>(-47, -10))[1], 44, 1e-12);
  EXPECT_TRUE(h.contains(Vec<2>(0, 1)));
  EXPECT_TRUE(h.contains(Vec<2>(-20, 30)));
  EXPECT_FALSE(h.contains(Vec<2>(-20, 10)));  // below the 45-degree wall (at x = -20 it is at y = 17)
  EXPECT_FALSE(h.contains(Vec<2>(3.5, 10)));  // beyond the vertical wall
  EXPECT_FALSE(h.contains(Vec<2>(-47.5, 60)));
  // mirrored: 0/45
  const Hopper<2> m(50, 6, 0, units::deg_to_rad(45));
  EXPECT_DOUBLE_EQ(m.x_min(), -3);
  EXPECT_DOUBLE_EQ(m.x_max(), 47);
  EXPECT_FALSE(m.has_wall(2));
  EXPECT_EQ(m.nearest_point(0, Vec<2>(-2.5, 30)), Vec<2>(-3, 30));
  // a polygon edge cutting the vertical wall inside the funnel is caught
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(2, 5), Vec<2>(4, 5)), 1);
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(1, 5), Vec<2>(2, 5)), -1);
}

TEST(Hopper2D, SymmetricWallsKeepTheContainerCentredOnTheOrifice) {
  const Hopper<2> h(50, 6, units::deg_to_rad(60), units::deg_to_rad(30));
  EXPECT_EQ(h.x_min(), -25);
  EXPECT_EQ(h.x_max(), 25);
  EXPECT_EQ(h.lateral_centre(), 0);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(h.has_wall(k));
}

TEST(Hopper2D, UnderASlopedFunnelWallIsOutsideYetNotBeyondTheWallsSpan) {
  // 20 deg walls (from gravity) rise by cot(20 deg) = 2.75 per unit of x from the orifice edges
  const Hopper<2> h(50, 4.2, units::deg_to_rad(20), units::deg_to_rad(20));
  const Vec<2> under_left(-2.4, 0.02), under_right(2.4, 0.5), inside(-2.1, 0.5), beside_side_wall(-25.5, 60);
  for (const Vec<2>& p : {under_left, under_right}) {
    EXPECT_FALSE(h.contains(p)) << p.transpose();
    EXPECT_TRUE(h.beneath_funnel_wall(p)) << p.transpose();
  }
  EXPECT_TRUE(h.contains(inside));
  EXPECT_FALSE(h.beneath_funnel_wall(inside));
  EXPECT_FALSE(h.beneath_funnel_wall(Vec<2>(-2.4, -0.02))) << "below the orifice plane is contains()'s";
  EXPECT_FALSE(h.beneath_funnel_wall(beside_side_wall)) << "beyond the side wall is outside, not under the funnel";
  // a flat floor's underside is below the plane; a vertical wall spans no x
  const Hopper<2> flat(50, 4.2, units::pi / 2, units::pi / 2), vertical(50, 4.2, units::deg_to_rad(30), 0);
  EXPECT_FALSE(flat.beneath_funnel_wall(Vec<2>(-3, 0.01)));
  EXPECT_FALSE(vertical.beneath_funnel_wall(Vec<2>(2.3, 1.0)));
  EXPECT_FALSE(vertical.contains(Vec<2>(2.3, 1.0)));
}

TEST(Hopper2D, SegmentsCuttingAFunnelWall) {
  const Hopper<2> h(50, 6, units::pi / 2, units::pi / 2);
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(2.5, 0.5), Vec<2>(2.5, -0.5)), -1);  // through the orifice
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(3.5, 0.5), Vec<2>(3.5, -0.5)), 1);   // through the right floor
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(-4, -0.1), Vec<2>(-3.5, 0.2)), 0);   // through the left floor
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(3.5, 0.5), Vec<2>(8, 0.1)), -1);     // above it
  EXPECT_EQ(h.funnel_wall_crossed(Vec<2>(3.5, -0.5), Vec<2>(8, -0.1)), -1);   // under it
  const Hopper<2> funnel(50, 6, units::deg_to_rad(45), units::deg_to_rad(45));
  EXPECT_EQ(funnel.funnel_wall_crossed(Vec<2>(4, 0.5), Vec<2>(5, 1.5)), -1);  // inside, along the wall
  EXPECT_EQ(funnel.funnel_wall_crossed(Vec<2>(4, 0.5), Vec<2>(4, 1.5)), 1);   // across the 45 degree wall
}

// beyond() is the wall masks' cheap test: it may say "maybe near" of a far wall, never "beyond"
// of a wall within reach; and it must reject most far walls, or it saves nothing.
template <int D>
void check_beyond_never_hides_a_wall_in_reach(const Hopper<D>& h, double span, int seed, double min_rejected = 0.5) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-span, span), up(-3, 2 * span), reach_of(0.1, 1.5);
  int rejected = 0, points = 0;
  for (int n = 0; n < 20000; ++n) {
    Vec<D> p;
    for (int d = 0; d < D; ++d) p[d] = coord(rng);
    p[D - 1] = up(rng);
    const double reach = reach_of(rng);
    for (int k = 0; k < Hopper<D>::kNumWalls; ++k) {
      ++points;
      const double dist = (p - h.nearest_point(k, p)).norm();
      if (!h.beyond(k, p, reach)) continue;
      ++rejected;
      EXPECT_GE(dist, reach) << "wall " << k << " at " << p.transpose() << " reach " << reach;
    }
    // points on a wall's reach boundary itself, where rounding decides
    const int k = n % Hopper<D>::kNumWalls;
    const Vec<D> on = h.nearest_point(k, p);
    if ((p - on).norm() > 0 && (p - on).norm() < 1e3) {
      const Vec<D> at = on + reach * (p - on).normalized();
      if (h.beyond(k, at, reach)) {
        EXPECT_GE((at - h.nearest_point(k, at)).squaredNorm(), reach * reach);
      }
    }
  }
  EXPECT_GT(rejected, min_rejected * points);
}

TEST(Hopper2D, BeyondNeverHidesAWallInReach) {
  check_beyond_never_hides_a_wall_in_reach<2>(Hopper<2>(50, 6, units::pi / 2, units::pi / 2), 30, 1);
  check_beyond_never_hides_a_wall_in_reach<2>(Hopper<2>(50, 6, units::deg_to_rad(60), units::deg_to_rad(30)), 30, 2);
  check_beyond_never_hides_a_wall_in_reach<2>(Hopper<2>(50, 6, units::deg_to_rad(45), 0), 50, 3);
  check_beyond_never_hides_a_wall_in_reach<2>(Hopper<2>(20, 4.5, units::deg_to_rad(10), units::deg_to_rad(80)), 15, 4);
}

TEST(Hopper3D, BeyondNeverHidesAWallInReach) {
  check_beyond_never_hides_a_wall_in_reach<3>(Hopper<3>(25, 6), 14, 5);
  check_beyond_never_hides_a_wall_in_reach<3>(Hopper<3>(3, 1), 2, 6, 0.2);  // narrow: most points near
}

TEST(Hopper3D, BaseAnnulusRimAndMantle) {
  const Hopper<3> h(25, 6);
  EXPECT_EQ(h.nearest_point(0, Vec<3>(5, 0, 0.3)), Vec<3>(5, 0, 0));     // on the base
  EXPECT_EQ(h.nearest_point(0, Vec<3>(0, 2, 0.3)), Vec<3>(0, 3, 0));     // rim (corner)
  EXPECT_EQ(h.nearest_point(1, Vec<3>(0, 12, 4)), Vec<3>(0, 12.5, 4));   // mantle
  EXPECT_EQ(h.nearest_point(1, Vec<3>(12, 0, -1)), Vec<3>(12.5, 0, 0));  // mantle's bottom rim
  EXPECT_TRUE(h.contains(Vec<3>(12, 0, 3)));
  EXPECT_FALSE(h.contains(Vec<3>(9, 9, 3)));
  EXPECT_TRUE(h.contains(Vec<3>(9, 9, -1)));  // below the base: no walls
}

template <int D>
void check_list_against_brute_force(int n, std::uint64_t seed) {
  SimConfig c = small_config(D, n, 3.0);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed);
  NeighborList<D> list(c.skin);
  list.build(s, h);
  std::set<std::pair<int, int>> listed;
  for (int i = 0; i < n; ++i) {
    int prev = -1;
    for (const int* p = list.row_begin(i); p != list.row_end(i); ++p) {
      EXPECT_GT(*p, i);
      EXPECT_GT(*p, prev) << "rows must be sorted";
      prev = *p;
      listed.insert({i, *p});
    }
  }
  // every pair within sigma_ij + skin is listed; every listed pair is within it
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double cut = 0.5 * (s.sigma(i) + s.sigma(j)) + c.skin;
      const bool near = (s.x[i] - s.x[j]).norm() < cut;
      EXPECT_EQ(near, listed.count({i, j}) == 1) << i << " " << j;
    }
  // after moving everybody less than half the skin, every overlapping pair is still listed
  Rng rng(seed + 5);
  for (auto& x : s.x)
    for (int d = 0; d < D; ++d) x[d] += rng.uniform(-0.49, 0.49) * c.skin / std::sqrt(double(D));
  EXPECT_FALSE(list.update(s, h)) << "no rebuild needed";
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((s.x[i] - s.x[j]).norm() < 0.5 * (s.sigma(i) + s.sigma(j))) {
        EXPECT_EQ(listed.count({i, j}), 1u);
      }
  s.x[0][0] += c.skin;  // one particle moved more than half the skin
  EXPECT_TRUE(list.update(s, h));
}

template <int D>
std::set<std::pair<int, int>> listed_pairs(const NeighborList<D>& list, int n) {
  std::set<std::pair<int, int>> out;
  for (int i = 0; i < n; ++i) {
    int prev = -1;
    for (const int* p = list.row_begin(i); p != list.row_end(i); ++p) {
      EXPECT_GT(*p, prev) << "rows must stay sorted";
      prev = *p;
      out.insert({i, *p});
    }
  }
  return out;
}

// The pair runs that build_sorting() writes while it builds are the ones the pass over the
// slots makes from the rows (after a restore, which has no runs of its own), block by block.
template <int D>
void check_pair_runs_of_the_build(int n, std::uint64_t seed) {
  SimConfig c = small_config(D, n, 3.0);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed), scratch;
  NeighborList<D> list(c.skin), again(c.skin);
  list.use_blocks(true);
  again.use_blocks(true);
  list.build_sorting(s, h, scratch);
  list.update_block_lists(s.species.data());
  again.restore(list.snapshot(), s.size());
  again.update_block_lists(s.species.data());
  ASSERT_GE(list.blocks(), 2);
  ASSERT_EQ(list.blocks(), again.blocks());
  for (int b = 0; b <= list.blocks(); ++b) ASSERT_EQ(list.pairs_begin(b), again.pairs_begin(b)) << "block " << b;
  const int pairs = list.pairs_begin(list.blocks());
  EXPECT_GT(pairs, n);
  for (int k = 0; k < pairs; ++k) {
    ASSERT_EQ(list.pair_i()[k], again.pair_i()[k]) << k;
    ASSERT_EQ(list.pair_j()[k], again.pair_j()[k]) << k;
    ASSERT_EQ(list.pair_type()[k], again.pair_type()[k]) << k;
  }
  for (int b = 0; b < list.blocks(); ++b)
    EXPECT_TRUE(std::equal(list.receivers_begin(b), list.receivers_end(b), again.receivers_begin(b), again.receivers_end(b)));
}

TEST(NeighborList, PairRunsOfTheSortingBuildEqualThoseFromTheRows) {
  check_pair_runs_of_the_build<2>(2400, 3);
  check_pair_runs_of_the_build<3>(3000, 4);
}

TEST(NeighborList, RelocateEqualsARebuild) {
  // Moving particles far (reinjection) and relocating them gives exactly the pairs and wall
  // masks that a fresh build would, in sorted rows.
  SimConfig c = small_config(2, 400, 3.0);
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 4);
  NeighborList<2> list(c.skin), fresh(c.skin);
  list.build(s, h);
  Rng rng(8);
  int relocated = 0;
  for (int k = 0; k < 20; ++k) {
    const int i = static_cast<int>(rng.below(s.size()));
    s.x[i] = Vec<2>(rng.uniform(-5.5, 5.5), rng.uniform(0.5, 30));  // far from where it was
    list.relocate(i, s, h);
    relocated += !list.update(s, h);  // false: no rebuild was needed
  }
  fresh.build(s, h);
  EXPECT_GT(relocated, 10) << "most relocations must fit into the rows' room";
  if (relocated == 20) {
    EXPECT_EQ(listed_pairs(list, s.size()), listed_pairs(fresh, s.size()));
    for (int i = 0; i < s.size(); ++i) EXPECT_EQ(list.wall_mask(i), fresh.wall_mask(i)) << i;
  } else {
    EXPECT_EQ(listed_pairs(list, s.size()), listed_pairs(fresh, s.size())) << "after the fallback rebuild";
  }
}

TEST(NeighborList, MatchesBruteForce2D) { check_list_against_brute_force<2>(400, 1); }
TEST(NeighborList, MatchesBruteForce3D) { check_list_against_brute_force<3>(500, 2); }

}  // namespace
}  // namespace beverloo
