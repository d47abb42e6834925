// Funnel walls with a thickness (dp.wall_thickness, engine/geometry/funnel_cores.h): a vertex
// that has entered the floor is pushed back out, harder the deeper it is; the lip is round; the
// energy is continuous on every path; a wall is gone through only past its core.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dp_support.h"
#include "engine/geometry/funnel_cores.h"

namespace beverloo {
namespace {
using testing::DpFixture;
using testing::dp_config;

struct ThickFloor {
  SimConfig c;
  DpFixture fx;
  Hopper<2> h;
  DpForceField ff;
  int j;  ///< the probe vertex (polygon 1's first), its polygon kept far above
  explicit ThickFloor(double thickness)
      : c(config(thickness)), fx(c, {{0.0, 4.0}, {0.0, 8.0}}, 0.0, 1), h(make_hopper<2>(fx.c)),
        ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c), j(fx.poly.first[1]) {}
  static SimConfig config(double thickness) {
    SimConfig c = dp_config("dp_smooth", 2);
    c.E_w = 50;
    c.dp.wall_width = 1;
    c.dp.wall_thickness = thickness;
    c.resolve_and_validate();
    return c;
  }
  /// The walls' energy and force on the probe vertex placed at p.
  double wall_energy(const Vec<2>& p, Vec<2>* force = nullptr) {
    fx.verts.x[j] = p;
    ff.list().build(fx.verts, h);
    VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
    const double e = ff.terms()[4]->accumulate(fx.verts, f).energy;  // hopper_walls
    if (force) *force = f[j];
    return e;
  }
  double l0() const { return fx.shape.l0[0]; }
};

TEST(ThickWalls, AVertexInsideTheFloorIsPushedBackOutHarderTheDeeperItIs) {
  ThickFloor t(1.0);
  const double T = t.l0(), sigma = t.fx.shape.wall[t.fx.verts.species[t.j]], x = -4.0;
  ASSERT_NEAR(t.ff.funnel_cores().half_thickness(), T / 2, 1e-15);
  double previous = 0;
  for (double y : {0.4 * sigma, 0.2 * sigma, 0.0, -0.1 * T, -0.25 * T, -0.45 * T}) {
    Vec<2> f;
    const double e = t.wall_energy(Vec<2>(x, y), &f);
    // d = |y + T/2| - T/2 = y above the core: U = (E_w/2)(1 - 2 y / sigma)^2
    const double expected = 0.5 * t.c.E_w * std::pow(1 - 2 * y / sigma, 2);
    EXPECT_NEAR(e, expected, 1e-9 * expected) << "y = " << y;
    EXPECT_GT(e, previous) << "y = " << y;
    EXPECT_GT(f[1], 0) << "pushed up at y = " << y;
    EXPECT_NEAR(f[0], 0, 1e-12);
    previous = e;
  }
  // A line wall (thickness 0) gives way: below its line it pushes the vertex further down.
  ThickFloor line(0.0);
  Vec<2> f;
  line.wall_energy(Vec<2>(x, -0.25 * T), &f);
  EXPECT_LT(f[1], 0);
}

TEST(ThickWalls, ForcesAreTheEnergysGradientAroundTheLipAndInsideTheWall) {
  ThickFloor t(1.0);
  const Vec<2> lip = t.ff.funnel_cores().lip_centre(1);
  const double half = t.h.orifice_half_width(), T = t.l0();
  // the lip's bead: centred T/2 beside the orifice edge and T/2 under the floor
  EXPECT_NEAR(lip[0], half + T / 2, 1e-12);
  EXPECT_NEAR(lip[1], -T / 2, 1e-12);
  const std::vector<Vec<2>> points = {
      {half + 0.1 * T, 0.3 * T}, {half - 0.2 * T, -0.2 * T}, {half + 0.3 * T, -0.1 * T},
      {half + 2 * T, -0.3 * T},  {half - 0.1 * T, -0.6 * T}, lip + Vec<2>(-0.6 * T, 0.55 * T)};
  for (const Vec<2>& p : points) {
    Vec<2> f;
    const double e0 = t.wall_energy(p, &f);
    EXPECT_GT(e0, 0) << p.transpose();
    const double eps = 1e-7;
    for (int d = 0; d < 2; ++d) {
      Vec<2> up = p, down = p;
      up[d] += eps;
      down[d] -= eps;
      const double numeric = -(t.wall_energy(up) - t.wall_energy(down)) / (2 * eps);
      EXPECT_NEAR(f[d], numeric, 1e-5 * std::max(1.0, std::fabs(f[d]))) << p.transpose() << " component " << d;
    }
  }
}

/// The walls' energy along a path over the floor, round the lip and under the floor at `depth`
/// below the core line (= T/2 + the gap: the path is closed), in `steps` steps.
std::vector<double> energy_along_lip_path(ThickFloor& t, int steps, double depth) {
  const double half = t.h.orifice_half_width(), T = t.l0(), gap = 0.3 * T;
  const Vec<2> lip = t.ff.funnel_cores().lip_centre(1);
  std::vector<double> energy;
  for (int k = 0; k <= steps; ++k) {
    const double s = double(k) / steps;
    Vec<2> p;
    if (s < 0.25)  // along the floor toward the orifice, gap above it
      p = Vec<2>(half + 2 * T - 4 * s * (1.5 * T), gap);
    else if (s < 0.75) {  // round the bead at gap from its surface, from the top to below it
      const double a = 0.5 * M_PI + 2 * (s - 0.25) * M_PI;
      p = lip + (T / 2 + gap) * Vec<2>(std::cos(a), std::sin(a));
    } else  // under the floor, outward: from under the lip into the slab's region
      p = lip + Vec<2>(4 * (s - 0.75) * 1.5 * T, -depth);
    energy.push_back(t.wall_energy(p));
  }
  return energy;
}

double largest_step(const std::vector<double>& e) {
  double largest = 0;
  for (std::size_t k = 1; k < e.size(); ++k) largest = std::max(largest, std::fabs(e[k] - e[k - 1]));
  return largest;
}

TEST(ThickWalls, EnergyIsContinuousAlongAPathOverTheLipAndUnderTheFloor) {
  // Along the floor, over the lip, down its inner side and out under the floor's underside, at
  // one gap from the wall's surface all the way: the energy is the gap's everywhere (the floor
  // is a solid T thick with a round lip; engine 0.6.2, before which the slab's push up reached
  // any depth).
  ThickFloor t(1.0);
  const double T = t.l0(), depth = 0.5 * T + 0.3 * T;
  const std::vector<double> path = energy_along_lip_path(t, 400, depth);
  const double at_gap = path.front();
  EXPECT_GT(at_gap, 0.5 * 0.5 * t.c.E_w * 0.16);
  for (std::size_t k = 0; k < path.size(); ++k) EXPECT_NEAR(path[k], at_gap, 1e-9 * at_gap) << "step " << k;
}

TEST(ThickWalls, EnergyIsContinuousThroughTheSlabsLowerHalfFromUnderTheLipOutward) {
  // Within T of the lip the slab's lower half turns over from the bead's push outward to the
  // slab's push back up (FunnelCores::slab_distance), steeply but continuously: ten times the
  // resolution makes the largest step about ten times smaller (a jump would stay).
  ThickFloor t(1.0);
  const double T = t.l0();
  const Vec<2> lip = t.ff.funnel_cores().lip_centre(1);
  auto along = [&](int steps) {
    std::vector<double> e;
    for (int k = 0; k <= steps; ++k) e.push_back(t.wall_energy(lip + Vec<2>(1.5 * T * k / steps, -0.3 * T)));
    return e;
  };
  const std::vector<double> coarse = along(400), fine = along(4000);
  EXPECT_GT(largest_step(coarse), 0);
  EXPECT_LT(largest_step(fine), 0.2 * largest_step(coarse));
  EXPECT_LT(largest_step(fine), 0.02 * 0.5 * t.c.E_w);
}

TEST(ThickWalls, BelowTheCoreTheFloorPushesBackUpAndItsForceIsTheEnergysGradient) {
  // Deep in the floor, away from the lip, the slab pushes a vertex up down to its bottom (as
  // the authors' bottom wall does down to the exit plane); within T of the lip it turns over to
  // the lip's push outward.
  ThickFloor t(1.0);
  const double T = t.l0(), x = -4.0;
  double previous = 0;
  for (double y : {-0.4 * T, -0.6 * T, -0.9 * T, -0.99 * T}) {
    Vec<2> f;
    const double e = t.wall_energy(Vec<2>(x, y), &f);
    EXPECT_GT(e, previous) << "y = " << y;
    EXPECT_GT(f[1], 0) << "pushed up at y = " << y;
    EXPECT_NEAR(f[0], 0, 1e-9);
    previous = e;
  }
  const Vec<2> lip = t.ff.funnel_cores().lip_centre(1);
  for (const Vec<2>& p : {Vec<2>(lip + Vec<2>(0.2 * T, -0.3 * T)), Vec<2>(lip + Vec<2>(0.7 * T, -0.4 * T)),
                          Vec<2>(lip + Vec<2>(1.5 * T, -0.6 * T)), Vec<2>(x, -0.7 * T)}) {
    Vec<2> f;
    t.wall_energy(p, &f);
    const double eps = 1e-7;
    for (int a = 0; a < 2; ++a) {
      Vec<2> hi = p, lo = p;
      hi[a] += eps;
      lo[a] -= eps;
      EXPECT_NEAR(f[a], -(t.wall_energy(hi) - t.wall_energy(lo)) / (2 * eps), 1e-5 * std::max(1.0, f.norm()))
          << "component " << a << " at " << p.transpose();
    }
  }
  Vec<2> f;
  t.wall_energy(lip + Vec<2>(0.1 * T, -0.3 * T), &f);
  EXPECT_LT(f[1], 0) << "just under the lip a vertex is pushed down, out of the wall";
}

TEST(ThickWalls, UnderTheSlabTheFloorsUndersidePushesDownAndNothingActsDeeper) {
  // The slab pushes up down to its bottom (T below the surface, the authors' exit plane); a
  // vertex under it (one that swung round the lip from the orifice) meets the floor's
  // underside, which pushes it down within its own reach, and nothing acts deeper. Engine
  // 0.6.0 and 0.6.1 pulled such a vertex up from any depth, but only as far as the list's
  // wall masks reached when the list was built: a resumed run (its list built afresh) left
  // the uninterrupted one. The list is built afresh at every position here.
  ThickFloor t(1.0);
  const double T = t.l0(), x = -4.0, sigma = t.fx.shape.wall[t.fx.verts.species[t.j]];
  Vec<2> f;
  EXPECT_GT(t.wall_energy(Vec<2>(x, -0.99 * T), &f), 0);
  EXPECT_GT(f[1], 0) << "inside the slab, down to its bottom: pushed up";
  const Vec<2> under(x, -T - 0.2 * sigma);
  EXPECT_NEAR(t.wall_energy(under, &f), 0.5 * t.c.E_w * std::pow(1 - 0.4, 2), 1e-9 * t.c.E_w);
  EXPECT_LT(f[1], 0) << "under the slab: pushed down, away from the floor";
  const double eps = 1e-7;
  EXPECT_NEAR(f[1],
              -(t.wall_energy(under + Vec<2>(0, eps)) - t.wall_energy(under - Vec<2>(0, eps))) / (2 * eps),
              1e-5 * std::max(1.0, std::fabs(f[1])));
  for (double y : {-T - 0.6 * sigma, -3.0 * T, -12.0 * T}) {
    EXPECT_EQ(t.wall_energy(Vec<2>(x, y), &f), 0) << "y = " << y;
    EXPECT_EQ(f, Vec<2>::Zero()) << "y = " << y;
  }
  const Vec<2> lip = t.ff.funnel_cores().lip_centre(1);
  for (double along : {0.1, 0.7, 2.0}) EXPECT_EQ(t.wall_energy(lip + Vec<2>(along * T, -8 * T)), 0);
  // a side wall of a thick container pushes back in from any distance beyond it: the list's
  // masks hold such a vertex whenever the list is built
  const double xs = t.h.x_max();
  double previous = 0;
  for (double beyond : {0.45 * T, 2.0 * T, 5.0 * T}) {
    const double e = t.wall_energy(Vec<2>(xs + beyond, 5.0), &f);
    EXPECT_NEAR(e, 0.5 * t.c.E_w * std::pow(1 + 2 * beyond / sigma, 2), 1e-6 * e) << "beyond " << beyond;
    EXPECT_LT(f[0], 0);
    EXPECT_GT(e, previous);
    previous = e;
  }
  // a vertex far from every wall has an empty mask (the walls' sweep skips it)
  t.wall_energy(Vec<2>(0.0, 6.0));
  EXPECT_EQ(t.ff.list().wall_mask(t.j), 0);
}

TEST(ThickWalls, SideWallsOfAThickContainerPushAVertexBackInFromBeyondThem) {
  ThickFloor t(1.0);
  const double xs = t.h.x_max(), y = 5.0, sigma = t.fx.shape.wall[t.fx.verts.species[t.j]];
  double previous = 0;
  for (double x : {xs - 0.4 * sigma, xs - 1e-9, xs + 1e-9, xs + 0.2 * t.l0(), xs + 0.45 * t.l0()}) {
    Vec<2> f;
    const double e = t.wall_energy(Vec<2>(x, y), &f);
    EXPECT_NEAR(e, 0.5 * t.c.E_w * std::pow(1 + 2 * (x - xs) / sigma, 2), 1e-6 * t.c.E_w) << "x - x_max = " << x - xs;
    EXPECT_GT(e, previous);
    EXPECT_LT(f[0], 0) << "pushed back in at x - x_max = " << x - xs;
    previous = e;
    const double eps = 1e-7;  // the force is the energy's gradient there
    EXPECT_NEAR(f[0], -(t.wall_energy(Vec<2>(x + eps, y)) - t.wall_energy(Vec<2>(x - eps, y))) / (2 * eps),
                1e-5 * std::max(1.0, std::fabs(f[0])));
  }
  ThickFloor line(0.0);  // a line side wall pushes a vertex beyond it further out
  Vec<2> f;
  line.wall_energy(Vec<2>(xs + 0.2 * line.l0(), y), &f);
  EXPECT_GT(f[0], 0);
}

TEST(ThickWalls, AWallIsGoneThroughOnlyPastItsSlab) {
  const Hopper<2> h(20, 4, M_PI / 2, M_PI / 2);
  const FunnelCores cores(h, 0.2);
  // an edge from above the floor to inside it (depth 0.05 < T/2 = 0.1, and 0.15 < T): not through
  EXPECT_EQ(cores.crossed(Vec<2>(5, 0.1), Vec<2>(5.2, -0.05)), -1);
  EXPECT_EQ(cores.crossed(Vec<2>(5, 0.1), Vec<2>(5.2, -0.15)), -1);
  // to beyond the slab's bottom (depth 0.25 > T): through the right wall
  EXPECT_EQ(cores.crossed(Vec<2>(5, 0.1), Vec<2>(5.2, -0.25)), 1);
  EXPECT_EQ(cores.crossed(Vec<2>(-5, 0.1), Vec<2>(-5.2, -0.25)), 0);
  // next to the lip, where the slab pushes outward, past the core is through
  const Vec<2> lip = cores.lip_centre(1);
  EXPECT_EQ(cores.crossed(lip + Vec<2>(0.05, 0.05), lip + Vec<2>(0.05, -0.05)), 1);
  // through the orifice, past the lip: nothing crossed
  EXPECT_EQ(cores.crossed(Vec<2>(1.8, 0.1), Vec<2>(1.8, -0.5)), -1);
  // inclined walls: the core lies T/2 behind the wall's line, parallel to it
  const Hopper<2> v(20, 4, M_PI / 3, M_PI / 3);
  const FunnelCores inclined(v, 0.2);
  const Vec<2> u = v.wall_direction(1), n = v.funnel_inward_normal(1), a = v.wall_start(1);
  EXPECT_GT(n[1], 0);  // inward: up, toward the axis
  EXPECT_LT(n[0], 0);
  const Vec<2> on_wall = a + 2.0 * u;
  EXPECT_NEAR((on_wall - inclined.nearest_point(1, on_wall)).norm(), 0.1, 1e-12);
  EXPECT_EQ(inclined.crossed(on_wall + 0.05 * n, on_wall - 0.05 * n), -1);
  EXPECT_EQ(inclined.crossed(on_wall + 0.05 * n, on_wall - 0.15 * n), -1);
  EXPECT_EQ(inclined.crossed(on_wall + 0.05 * n, on_wall - 0.25 * n), 1);
}

}  // namespace
}  // namespace beverloo
