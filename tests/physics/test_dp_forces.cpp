// DP force terms (physics.md 4): every term against finite differences on randomly deformed
// polygons, the smooth contact against an independent brute-force evaluation (every edge
// against every vertex of the other polygons, both ways), its corner case, momentum,
// rigid-motion invariance and dissipation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "dp_support.h"
#include "engine/integrate/velocity_verlet.h"
#include "engine/models/authors_dp_set.h"

namespace beverloo {
namespace {
using testing::DpFixture;
using testing::dp_config;

/// Polygons pressed together: neighbours' centres closer than their diameters.
std::vector<Vec<2>> cluster() {
  return {{-0.9, 3.0}, {0.05, 3.05}, {1.0, 2.95}, {-0.45, 3.85}, {0.5, 3.9}, {0.0, 2.1}, {-4.5, 0.55}, {4.2, 2.0}};
}

/// Central differences of every conservative term for every vertex coordinate.
void check_gradients(DpFixture& fx, int min_terms_with_energy) {
  if (fx.poly.polygons() == int(cluster().size())) {
    fx.verts.x[fx.poly.first[6]] = Vec<2>(-4.5, 0.005);  // on the floor, inside the wall's reach
    fx.verts.x[fx.poly.first[7] + 4] = Vec<2>(5.997, 2.3);  // on the side wall
  }
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.set_dissipation(false);
  ParticleState<2>& s = fx.verts;
  ff.compute(s);  // sets the edge search bounds for these (perhaps stretched) edges
  int with_energy = 0;
  for (ForceTerm<2>* term : ff.terms()) {
    auto energy = [&] {
      ff.list().build(s, h);
      VecArray<2> f(s.size(), Vec<2>::Zero());
      return term->accumulate(s, f).energy;
    };
    ff.list().build(s, h);
    VecArray<2> f(s.size(), Vec<2>::Zero());
    const double e0 = term->accumulate(s, f).energy;
    if (e0 != 0) ++with_energy;
    const double eps = 1e-7;
    for (int i = 0; i < s.size(); ++i)
      for (int d = 0; d < 2; ++d) {
        const double keep = s.x[i][d];
        s.x[i][d] = keep + eps;
        const double up = energy();
        s.x[i][d] = keep - eps;
        const double down = energy();
        s.x[i][d] = keep;
        const double numeric = -(up - down) / (2 * eps);
        ASSERT_NEAR(f[i][d], numeric, 1e-4 * std::max(1.0, std::fabs(f[i][d])))
            << term->name() << " vertex " << i << " component " << d;
      }
  }
  EXPECT_GE(with_energy, min_terms_with_energy);
}

TEST(DpForces, GradientsSmoothDeformed) {
  DpFixture fx(dp_config("dp_smooth", 8), cluster(), 0.2, 3);
  check_gradients(fx, 6);  // area, segments, bending, contact, walls, gravity
}

TEST(DpForces, GradientsRoughDeformed) {
  DpFixture fx(dp_config("dp_rough", 8), cluster(), 0.2, 4);
  check_gradients(fx, 6);
}

TEST(DpForces, GradientsSmoothSoftShapes) {
  SimConfig c = dp_config("dp_smooth", 8);
  c.dp.K_l = 1;
  c.dp.K_b = 1e-2;
  c.dp.E_c = 1e2;
  DpFixture fx(c, cluster(), 0.35, 5);
  check_gradients(fx, 6);
}

/// Independent evaluation: every edge of every polygon against every vertex of the others,
/// distance from the clamped foot point (start vertex before the edge, nothing after it),
/// the start-vertex branch only outside the previous edge's slab.
double brute_force_smooth_energy(const DpFixture& fx, double eps_c, int edges_of = -1) {
  const auto& p = fx.poly;
  const auto& x = fx.verts.x;
  double energy = 0;
  for (int a = 0; a < p.vertices(); ++a)
    for (int b = 0; b < p.vertices(); ++b) {
      if (edges_of >= 0 && p.owner[a] != edges_of) continue;
      if (b == a || b == p.next[a]) continue;  // self-contact: every vertex but the edge's own ends
      const Vec<2> e = x[p.next[a]] - x[a], q = x[b] - x[a];
      const double t = q.dot(e) / e.squaredNorm();
      const double dmn = 0.5 * (fx.shape.delta[fx.verts.species[a]] + fx.shape.delta[fx.verts.species[b]]);
      double d;
      if (t >= 0 && t <= 1) {
        d = std::fabs(e[1] * q[0] - e[0] * q[1]) / e.norm();
        if (d >= dmn) continue;
      } else if (b == p.prev[a] || b == p.next[p.next[a]]) {  // fold pair: capped at the shared vertex only
        d = b == p.prev[a] ? (t < 0 ? q.norm() : 1e9) : (t > 1 ? (x[b] - x[p.next[a]]).norm() : 1e9);
        if (d >= dmn) continue;
      } else if (t < 0 && (x[b] - x[p.prev[a]]).dot(x[a] - x[p.prev[a]]) / (x[a] - x[p.prev[a]]).squaredNorm() > 1) {
        d = q.norm();
        if (d >= dmn) continue;
      } else {
        continue;
      }
      energy += 0.5 * eps_c * (1 - d / dmn) * (1 - d / dmn);
    }
  // A vertex within delta of a corner and in the slabs of both edges there is counted by both:
  // the corner's energy once less (continuous where it leaves either slab).
  for (int a = 0; a < p.vertices(); ++a)
    for (int b = 0; b < p.vertices(); ++b) {
      if (edges_of >= 0 && p.owner[a] != edges_of) continue;
      if (b == a || b == p.next[a] || b == p.prev[a]) continue;
      const Vec<2> e = x[p.next[a]] - x[a], ep = x[a] - x[p.prev[a]];
      const double t = (x[b] - x[a]).dot(e) / e.squaredNorm();
      const double t_prev = (x[b] - x[p.prev[a]]).dot(ep) / ep.squaredNorm();
      const double dmn = 0.5 * (fx.shape.delta[fx.verts.species[a]] + fx.shape.delta[fx.verts.species[b]]);
      const double d = (x[b] - x[a]).norm();
      if (t < 0 || t > 1 || t_prev < 0 || t_prev > 1 || d >= dmn) continue;
      energy -= 0.5 * eps_c * (1 - d / dmn) * (1 - d / dmn);
    }
  return energy;
}

/// The authors' code's forms (dp.K_l_large, dp.K_a_large, dp.E_c_vertex, dp.wall_width; the
/// values of docs/authors-model.md): every term still the gradient of its energy.
SimConfig authors_forms(const std::string& model) {
  SimConfig c = dp_config(model, 8);
  use_authors_dp_set(c);
  c.resolve_and_validate();
  return c;
}
TEST(DpForces, GradientsSmoothAuthorsForms) {
  DpFixture fx(authors_forms("dp_smooth"), cluster(), 0.2, 3);
  check_gradients(fx, 6);
}
TEST(DpForces, GradientsRoughAuthorsForms) {
  DpFixture fx(authors_forms("dp_rough"), cluster(), 0.2, 4);
  check_gradients(fx, 6);
}

/// Each form acts where it says and only there: the large species' K_l and K_a scale the
/// large polygons' shape energies alone; dp.wall_width widens the walls' reach; dp.E_c_vertex
/// scales the corner (vertex-vertex) contacts alone.
TEST(DpForces, AuthorsFormsActOnTheirOwnSpeciesAndBranches) {
  auto shape_energies = [](const SimConfig& c, const DpFixture& fx, const std::string& term_name) {
    const Hopper<2> h = make_hopper<2>(c);
    DpFixture copy = fx;
    copy.c = c;
    DpForceField ff(c, h, copy.poly, copy.shape, c.dp.E_c);
    ff.compute(copy.verts);
    std::array<double, 2> by_species{0, 0};
    for (ForceTerm<2>* term : ff.terms()) {
      if (term->name() != term_name) continue;
      // one polygon at a time: each polygon's energy from a state with it alone deformed
      for (int m = 0; m < copy.poly.polygons(); ++m) {
        ParticleState<2> s = fx.verts;
        for (int k = 0; k < copy.poly.polygons(); ++k)
          if (k != m)
            place_regular_polygon(copy.poly, copy.shape, s, k, Vec<2>(-5.0 + k, 9.0), 0.0, Vec<2>::Zero());
        VecArray<2> f(s.size(), Vec<2>::Zero());
        by_species[m % 2] += term->accumulate(s, f).energy;
      }
    }
    return by_species;
  };
  SimConfig base = dp_config("dp_smooth", 8);
  base.dp.K_a = 50;  // an area term whose energy is well above rounding
  base.resolve_and_validate();
  DpFixture fx(base, cluster(), 0.2, 9);
  SimConfig large = base;
  large.dp.K_l_large = 3 * base.dp.K_l;
  large.dp.K_a_large = 0.5 * base.dp.K_a;
  for (const auto& [term, factor] : {std::pair<std::string, double>{"dp_segment_length", 3.0}, {"dp_area", 0.5}}) {
    const auto e0 = shape_energies(base, fx, term), e1 = shape_energies(large, fx, term);
    ASSERT_GT(e0[0], 0) << term;
    ASSERT_GT(e0[1], 0) << term;
    EXPECT_DOUBLE_EQ(e1[0], e0[0]) << term << ": the small species keeps its stiffness";
    EXPECT_NEAR(e1[1], factor * e0[1], 1e-12 * e0[1]) << term << ": the large species has its own";
  }

  // a regular small polygon with one vertex 0.3 l0 above the floor: out of reach of a wall
  // contact as wide as the smooth contact (0.1 l0 / 2), in reach of one l0 wide
  SimConfig narrow = dp_config("dp_smooth", 2);
  DpFixture one(narrow, {Vec<2>(-4.0, 3.0), Vec<2>(4.0, 6.0)}, 0.0, 1);  // above the floor, not the orifice
  const double l0 = one.shape.l0[0];
  Vec<2> lowest = one.verts.x[0];
  for (int i = one.poly.first[0]; i < one.poly.first[1]; ++i) lowest = one.verts.x[i][1] < lowest[1] ? one.verts.x[i] : lowest;
  const Vec<2> shift(0.0, 0.3 * l0 - lowest[1]);
  for (int i = one.poly.first[0]; i < one.poly.first[1]; ++i) one.verts.x[i] += shift;
  auto wall_energy = [&](const SimConfig& c) {
    DpFixture fx1 = one;
    fx1.c = c;
    fx1.shape = DpShape::from_config(c);
    const Hopper<2> h = make_hopper<2>(c);
    DpForceField ff(c, h, fx1.poly, fx1.shape, c.dp.E_c);
    return ff.compute(fx1.verts).U_wall;
  };
  SimConfig wide = narrow;
  wide.dp.wall_width = 1;
  EXPECT_EQ(wall_energy(narrow), 0);
  EXPECT_GT(wall_energy(wide), 0) << "a vertex 0.3 l0 from the floor is within a wall contact l0 wide";
}

TEST(DpForces, SmoothContactMatchesBruteForceBothWays) {
  DpFixture fx(dp_config("dp_smooth", 8), cluster(), 0.2, 6);
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.list().build(fx.verts, h);
  VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
  const double e = ff.terms()[3]->accumulate(fx.verts, f).energy;
  ASSERT_GT(e, 0);
  EXPECT_NEAR(e, brute_force_smooth_energy(fx, fx.c.dp.E_c), 1e-10 * e);
  // relabelled: the polygons in reverse order give the same energy (pairs seen the other way)
  ParticleState<2> rev = fx.verts;
  const int nv = fx.c.dp.n_v, np = fx.poly.polygons();
  for (int m = 0; m < np; ++m)
    for (int k = 0; k < nv; ++k) {
      rev.x[m * nv + k] = fx.verts.x[(np - 1 - m) * nv + k];
      rev.species[m * nv + k] = fx.verts.species[(np - 1 - m) * nv + k];
    }
  ff.list().build(rev, h);
  VecArray<2> g(rev.size(), Vec<2>::Zero());
  EXPECT_NEAR(ff.terms()[3]->accumulate(rev, g).energy, e, 1e-10 * e);
}

TEST(DpForces, RoughPolygonFoldedOntoItselfRepelsItsOwnVertices) {
  // a rough polygon far from the other one: regular, no contact energy (ring neighbours are
  // left out); folded so that vertex 0 sits half a disk inside vertex 5, the disks repel with
  // the pair energy E_c/2 (1 - d/l0)^2 and the forces are equal and opposite
  DpFixture fx(dp_config("dp_rough", 2), {Vec<2>(-3, 5), Vec<2>(3, 5)}, 0.0, 1);
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ForceTerm<2>& contact = *ff.terms()[3];
  ff.list().build(fx.verts, h);
  VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
  EXPECT_EQ(contact.accumulate(fx.verts, f).energy, 0.0);
  const double l0 = fx.shape.l0[0];
  const Vec<2> inward = (Vec<2>(-3, 5) - fx.verts.x[5]).normalized();  // clear of vertices 4 and 6
  fx.verts.x[0] = fx.verts.x[5] + 0.5 * l0 * inward;
  ff.list().build(fx.verts, h);
  for (auto& fi : f) fi.setZero();
  const double e = contact.accumulate(fx.verts, f).energy;
  EXPECT_NEAR(e, 0.5 * fx.c.dp.E_c * 0.25, 1e-9 * e);
  EXPECT_LT((f[0] + f[5]).norm(), 1e-9 * f[0].norm());
  EXPECT_GT(f[0].dot(inward), 0);  // pushed away from vertex 5
}

TEST(DpForces, SmoothContactSearchFollowsStretchedEdges) {
  // Soft segments stretch edges to several l0. A vertex near the far end of such an edge is
  // farther from both end vertices than the list reach of regular polygons: the contact
  // search must grow with the edge, or the vertex passes through the edge unseen.
  DpFixture fx(dp_config("dp_smooth", 2), {Vec<2>(-3, 5), Vec<2>(3, 5)}, 0.0, 2);
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  const double l0 = fx.shape.l0[0];
  const int a = 0, an = fx.poly.next[0];
  fx.verts.x[an] = fx.verts.x[a] + 6 * l0 * (fx.verts.x[an] - fx.verts.x[a]).normalized();  // edge 0 -> 6 l0 (small)
  const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
  const Vec<2> normal(e[1] / e.norm(), -e[0] / e.norm());
  const int b = fx.poly.first[1] + 3;  // a vertex of the other polygon, mid-edge (3 l0 from both ends), outside
  fx.verts.x[b] = fx.verts.x[a] + 0.5 * e + 0.5 * fx.shape.delta[0] * normal;
  const double regular_reach = DpForceField::kEdgeBoundFloor * fx.shape.l0[1] + fx.shape.delta[0] + fx.c.skin;
  ASSERT_GT((fx.verts.x[b] - fx.verts.x[a]).norm(), regular_reach);
  ASSERT_GT((fx.verts.x[b] - fx.verts.x[an]).norm(), regular_reach);
  const ForceReport r = ff.compute(fx.verts);
  const double expected = brute_force_smooth_energy(fx, fx.c.dp.E_c);
  ASSERT_GT(expected, 0);
  EXPECT_NEAR(r.U_contact, expected, 1e-10 * expected);
  EXPECT_GE(ff.edge_bound(a), 6 * l0);
  EXPECT_LT(ff.edge_bound(fx.poly.first[1]), 2 * l0);  // the other polygon's edges keep their reach
}

TEST(DpForces, SmoothContactListReachesAVertexAtTheMiddleOfARegularEdge) {
  // The farthest a vertex in contact can be from an edge's nearer end: at the middle of the
  // edge, just inside the width, sqrt(w^2 + |e|^2/4) away. With a skin of almost nothing the
  // list's own reach (DpForceField::edge_reach) must cover it for every species pair.
  for (int edge_owner : {0, 1}) {
    SimConfig c = dp_config("dp_smooth", 2);
    c.skin = 1e-9;
    DpFixture fx(c, {Vec<2>(-4, 5), Vec<2>(4, 5)}, 0.0, 3);
    const Hopper<2> h = make_hopper<2>(fx.c);
    DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
    const int a = fx.poly.first[edge_owner], an = fx.poly.next[a];
    const int b = fx.poly.first[1 - edge_owner] + 5;
    const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
    const Vec<2> normal(e[1] / e.norm(), -e[0] / e.norm());
    const double w = 0.5 * (fx.shape.delta[edge_owner] + fx.shape.delta[1 - edge_owner]);
    fx.verts.x[b] = fx.verts.x[a] + 0.5 * e + 0.99 * w * normal;
    const ForceReport r = ff.compute(fx.verts);
    const double expected = brute_force_smooth_energy(fx, fx.c.dp.E_c);
    ASSERT_GT(expected, 0);
    EXPECT_NEAR(r.U_contact, expected, 1e-10 * expected) << "edge of species " << edge_owner;
  }
}

TEST(DpForces, SmoothContactCountsEveryVertexJustInsideTheWidthAlongAnEdgeAndPastItsEnds) {
  // edges_at_vertex skips, before edge_vertex, a vertex farther than the width from an edge's
  // line, and one whose foot lies beyond the edge's end or before its start out of the start
  // corner's reach: inside the width it must still count the slab, and past the edge's ends
  // the corners; just outside, nothing. A vertex slid along a line parallel to an edge, from
  // before its start to beyond its end, at 0.5, 0.999 and 1.001 widths, against the
  // brute-force sum over every edge and vertex.
  SimConfig c = dp_config("dp_smooth", 2);
  DpFixture fx(c, {Vec<2>(-4, 5), Vec<2>(4, 5)}, 0.0, 3);
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  const int a = fx.poly.first[0], an = fx.poly.next[a];
  const int b = fx.poly.first[1] + 5;
  const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
  const Vec<2> normal(e[1] / e.norm(), -e[0] / e.norm());
  const double w = 0.5 * (fx.shape.delta[fx.verts.species[a]] + fx.shape.delta[fx.verts.species[b]]);
  int touching = 0;
  for (const double across : {0.5, 0.999, 1.001})
    for (double along = -0.3; along <= 1.3; along += 0.0125) {
      fx.verts.x[b] = fx.verts.x[a] + along * e + across * w * normal;
      const ForceReport r = ff.compute(fx.verts);
      const double expected = brute_force_smooth_energy(fx, fx.c.dp.E_c);
      EXPECT_NEAR(r.U_contact, expected, 1e-12 + 1e-10 * expected) << "along " << along << ", " << across << " widths";
      touching += expected > 0;
    }
  EXPECT_GT(touching, 160) << "the slab inside the width touches all along the edge, and the corners past its ends";
}

/// Rough edge core, independently: every edge against every vertex of another polygon or of
/// its own polygon but the edge's ends and their other ring neighbours, slab only (0 <= t <= 1).
double brute_force_rough_core_energy(const DpFixture& fx, double eps_c) {
  const auto width = DpSmoothContact::core_widths(fx.shape);
  const auto& p = fx.poly;
  const int nv = p.vertices();
  double energy = 0;
  for (int i = 0; i < nv; ++i)
    for (int j = 0; j < nv; ++j) {
      if (j == i || j == p.next[i] || j == p.prev[i] || j == p.next[p.next[i]]) continue;  // ends, folds
      const Vec<2> a = fx.verts.x[i], e = fx.verts.x[fx.poly.next[i]] - a, q = fx.verts.x[j] - a;
      const double t = q.dot(e) / e.squaredNorm();
      if (t < 0 || t > 1) continue;
      const double d = std::fabs(q.dot(Vec<2>(e[1], -e[0]))) / e.norm();
      const double dmn = 0.5 * (width[fx.verts.species[i]] + width[fx.verts.species[j]]);
      if (d < dmn) energy += 0.5 * eps_c * (1 - d / dmn) * (1 - d / dmn);
    }
  return energy;
}

TEST(DpForces, RoughEdgeCoreHoldsVerticesOutOfStretchedEdges) {
  // A soft rough polygon's edge stretched to 4 l0 leaves a gap between its end disks wide
  // enough for a vertex to pass. The core (width l0/2) along the edge stops a vertex of
  // another polygon and one of the edge's own polygon; it is invisible to the disks' list reach,
  // so this also tests that the search follows the stretched edge.
  DpFixture fx(dp_config("dp_rough", 8), cluster(), 0.0, 9);
  const int a = fx.poly.first[5], an = fx.poly.next[a];
  const double l0 = fx.shape.l0[1], core = 0.5 * l0;  // polygon 5 and 1 are both large
  const double eps_core = DpSmoothContact::kRoughCoreEnergyFraction * fx.c.dp.E_c;
  fx.verts.x[an] = fx.verts.x[a] + 4 * l0 * (fx.verts.x[an] - fx.verts.x[a]).normalized();
  const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
  const Vec<2> out(e[1] / e.norm(), -e[0] / e.norm());
  const int own = fx.poly.first[5] + 8, other = fx.poly.first[1] + 3;
  fx.verts.x[other] = fx.verts.x[a] + 0.5 * e + 0.4 * core * out;   // outside, mid-edge
  fx.verts.x[own] = fx.verts.x[a] + 0.3 * e - 0.3 * core * out;     // inside, folded in
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.set_dissipation(false);
  ff.compute(fx.verts);
  ForceTerm<2>& edge_core = *ff.terms()[8];
  ASSERT_EQ(edge_core.name(), "dp_rough_edge_core");
  VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
  const double energy = edge_core.accumulate(fx.verts, f).energy;
  const double constructed = 0.5 * eps_core * (0.6 * 0.6 + 0.7 * 0.7);
  EXPECT_GE(energy, constructed * (1 - 1e-12));
  EXPECT_NEAR(energy, brute_force_rough_core_energy(fx, eps_core), 1e-10 * energy);
  EXPECT_GT(f[other].dot(out), 0);  // pushed back out
  EXPECT_LT(f[own].dot(out), 0);    // pushed back in
  Vec<2> total = Vec<2>::Zero();
  for (const auto& fi : f) total += fi;
  EXPECT_LT(total.norm(), 1e-9 * f[other].norm());
  // and the usual finite-difference check of every term, the core included
  check_gradients(fx, 7);
}

/// Rough fold barrier, independently: every edge against the vertex one place beyond either of
/// its ends (same polygon), slab and a cap at the shared vertex, width kRoughFoldWidth l0.
double brute_force_rough_fold_energy(const DpFixture& fx, double eps_fold) {
  const auto& p = fx.poly;
  double energy = 0;
  for (int i = 0; i < p.vertices(); ++i)
    for (int j : {p.prev[i], p.next[p.next[i]]}) {
      const Vec<2> a = fx.verts.x[i], e = fx.verts.x[p.next[i]] - a, q = fx.verts.x[j] - a;
      const double t = q.dot(e) / e.squaredNorm();
      double d = std::fabs(q.dot(Vec<2>(e[1], -e[0]))) / e.norm();
      if (t < 0) d = j == p.prev[i] ? q.norm() : 1e9;  // capped at the shared vertex only
      if (t > 1) d = j == p.prev[i] ? 1e9 : (fx.verts.x[j] - fx.verts.x[p.next[i]]).norm();
      const double dmn = DpSmoothContact::kRoughFoldWidth * fx.shape.l0[fx.verts.species[i]];
      if (d < dmn) energy += 0.5 * eps_fold * (1 - d / dmn) * (1 - d / dmn);
    }
  return energy;
}

TEST(DpForces, RoughPolygonFoldedAtAVertexMeetsTheFoldBarrier) {
  // Vertex k's interior angle closed until its ring neighbour prev(k) lies on the edge
  // k -> next(k), inside, half the barrier's width from it: a polygon folding through itself
  // at one vertex, which neither the disks (prev(k) and next(k) stay ~l0 apart along a
  // stretched edge) nor the core (it leaves out the edge's ring neighbours) would stop.
  DpFixture fx(dp_config("dp_rough", 2), {Vec<2>(-3, 5), Vec<2>(3, 5)}, 0.0, 3);
  const double l0 = fx.shape.l0[0];
  const int k = fx.poly.first[0] + 4, kp = fx.poly.prev[k], kn = fx.poly.next[k];
  const double eps_fold = DpSmoothContact::kRoughFoldWidth * DpSmoothContact::kRoughFoldWidth * fx.c.dp.E_c;
  const double width = DpSmoothContact::kRoughFoldWidth * l0;
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.set_dissipation(false);
  ForceTerm<2>& fold = *ff.terms()[9];
  ASSERT_EQ(fold.name(), "dp_rough_fold_barrier");
  ff.compute(fx.verts);
  VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
  EXPECT_EQ(fold.accumulate(fx.verts, f).energy, 0.0);  // regular: nothing folds
  fx.verts.x[kn] = fx.verts.x[k] + 2.0 * l0 * (fx.verts.x[kn] - fx.verts.x[k]).normalized();  // stretched
  const Vec<2> e = fx.verts.x[kn] - fx.verts.x[k];
  const Vec<2> out(e[1] / e.norm(), -e[0] / e.norm());
  fx.verts.x[kp] = fx.verts.x[k] + 0.3 * e - 0.5 * width * out;  // 0.6 l0 along, just inside
  ff.compute(fx.verts);
  for (auto& fi : f) fi.setZero();
  const double energy = fold.accumulate(fx.verts, f).energy;
  EXPECT_NEAR(energy, 0.5 * eps_fold * 0.25, 1e-9 * energy);
  EXPECT_NEAR(energy, brute_force_rough_fold_energy(fx, eps_fold), 1e-12 * energy);
  EXPECT_LT(f[kp].dot(out), 0);  // pushed back in, unfolding the vertex
  Vec<2> total = Vec<2>::Zero();
  for (const auto& fi : f) total += fi;
  EXPECT_LT(total.norm(), 1e-9 * f[kp].norm());
  check_gradients(fx, 5);

  // prev(k) slides along the edge to k, half the width inside, then around k at that distance
  // (the edge prev(k) -> k compressed below the width): no jump where it leaves the slab
  const Vec<2> along = e.normalized();
  double previous = -1;
  for (int step = 0; step <= 60; ++step) {
    const double half = 0.5 * width;
    if (step <= 20) {
      fx.verts.x[kp] = fx.verts.x[k] + (0.02 * (20 - step)) * l0 * along - half * out;
    } else {
      const double phi = 0.5 * units::pi * (step - 20) / 40.0;  // from -out toward -along
      fx.verts.x[kp] = fx.verts.x[k] - half * (std::cos(phi) * out + std::sin(phi) * along);
    }
    ff.compute(fx.verts);
    for (auto& fi : f) fi.setZero();
    const double u = fold.accumulate(fx.verts, f).energy;
    EXPECT_NEAR(u, brute_force_rough_fold_energy(fx, eps_fold), 1e-9 * eps_fold) << "step " << step;
    EXPECT_GE(u, 0.5 * eps_fold * 0.25 * (1 - 1e-9)) << "step " << step;  // the shared vertex's cap holds
    if (previous >= 0) {
      EXPECT_LT(std::fabs(u - previous), 0.05 * eps_fold) << "jump at step " << step;
    }
    previous = u;
  }
}

TEST(DpForces, SmoothPolygonFoldedOntoItselfRepelsItsOwnVerticesWithoutFriction) {
  // Vertex 8 of polygon 0 folded onto the polygon's edge 0 -> 1 from inside, half the edge width
  // away: the polygon's own edge repels it (E_c/2 (1/2)^2, nothing else touches), and the two
  // rub not: kinetic friction acts between particles only.
  DpFixture fx(dp_config("dp_smooth", 2), {Vec<2>(-3, 5), Vec<2>(3, 5)}, 0.0, 2);
  const int a = fx.poly.first[0], an = fx.poly.next[a], own = fx.poly.first[0] + 8;
  const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
  const Vec<2> out(e[1] / e.norm(), -e[0] / e.norm());
  fx.verts.x[own] = fx.verts.x[a] + 0.5 * e - 0.5 * fx.shape.delta[0] * out;
  fx.verts.v[own] = Vec<2>(1.0, -2.0);
  fx.c.mu = 10;
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  const ForceReport r = ff.compute(fx.verts);
  EXPECT_NEAR(r.U_contact, 0.5 * fx.c.dp.E_c * 0.25, 1e-9 * r.U_contact);
  EXPECT_NEAR(r.U_contact, brute_force_smooth_energy(fx, fx.c.dp.E_c), 1e-9 * r.U_contact);
  EXPECT_EQ(r.P_friction, 0.0);
  VecArray<2> friction;
  ff.friction_forces(fx.verts, friction);
  for (const auto& fi : friction) EXPECT_EQ(fi.norm(), 0.0);
  check_gradients(fx, 4);
}

/// Polygon 0 at (0, 3) and a probe: vertex j of polygon 1, pulled to any point while its
/// polygon stays rigidly far out along a given direction (a spike). The smooth contact's energy.
struct CornerProbe {
  SimConfig c = dp_config("dp_smooth", 2);
  DpFixture fx{c, {{0.0, 3.0}, {0.0, 6.0}}, 0.0, 1};
  Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff{fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c};
  const int corner = 3, j = fx.poly.first[1];
  double contact_energy(const Vec<2>& pos, const Vec<2>& out) {
    place_regular_polygon(fx.poly, fx.shape, fx.verts, 1, pos + 3.0 * out, 0.0, Vec<2>::Zero());
    fx.verts.x[j] = pos;
    ff.list().build(fx.verts, h);
    VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
    return ff.terms()[3]->accumulate(fx.verts, f).energy;
  }
};

TEST(DpForces, SmoothCornerCaseIsContinuousAndCountedOnce) {
  // Vertex j of polygon 1 (a spike: its polygon is far away, its edges point away) travels
  // inside the contact shell of polygon 0 along edge i-1, around the convex corner i on an
  // arc, and along edge i. The energy of polygon 0's edges against j must stay constant: the
  // shell has constant thickness, the vertex is counted once, nothing jumps at the slab
  // boundaries. The engine's total must equal the brute-force total at every point.
  CornerProbe probe;
  const SimConfig& c = probe.c;
  DpFixture& fx = probe.fx;
  auto& x = fx.verts.x;
  const int corner = probe.corner;
  const Vec<2> r = x[corner];
  const Vec<2> e_in = (r - x[fx.poly.prev[corner]]).normalized(), e_out = (x[fx.poly.next[corner]] - r).normalized();
  const Vec<2> n_in(e_in[1], -e_in[0]), n_out(e_out[1], -e_out[0]);
  const double delta = 0.5 * (fx.shape.delta[0] + fx.shape.delta[1]), gap = 0.6 * delta;
  const double a0 = std::atan2(n_in[1], n_in[0]);
  double da = std::atan2(n_out[1], n_out[0]) - a0;
  if (da < 0) da += 2 * units::pi;
  ASSERT_GT(da, 0.05);
  const double expected = 0.5 * c.dp.E_c * 0.4 * 0.4;
  double previous = -1;
  for (int k = -20; k <= 60; ++k) {
    Vec<2> pos;
    if (k < 0)
      pos = r + gap * n_in + (0.01 * k * fx.shape.l0[0]) * e_in;
    else if (k > 40)
      pos = r + gap * n_out + (0.01 * (k - 40) * fx.shape.l0[0]) * e_out;
    else
      pos = r + gap * Vec<2>(std::cos(a0 + da * k / 40.0), std::sin(a0 + da * k / 40.0));
    // polygon 1 rigidly far out along the local normal, then its vertex j pulled to pos
    const Vec<2> out = k < 0 ? n_in : k > 40 ? n_out : Vec<2>((pos - r).normalized());
    const double total = probe.contact_energy(pos, out);
    EXPECT_NEAR(total, brute_force_smooth_energy(fx, c.dp.E_c), 1e-9 * expected) << "step " << k;
    const double on_polygon0 = brute_force_smooth_energy(fx, c.dp.E_c, /*edges_of=*/0);
    EXPECT_NEAR(on_polygon0, expected, 1e-9 * expected) << "step " << k;
    // the spike folds polygon 1 onto itself (self-contact, which varies as it turns): leave it out
    const double engine_on_polygon0 = total - brute_force_smooth_energy(fx, c.dp.E_c, /*edges_of=*/1);
    if (previous >= 0) {  // a double count would jump by `expected`
      EXPECT_LT(std::fabs(engine_on_polygon0 - previous), 0.25 * expected) << "jump at step " << k;
    }
    previous = engine_on_polygon0;
  }
}

TEST(DpForces, ContactForcesConserveMomentumAndFrictionDissipates) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    DpFixture fx(dp_config(model, 8, 0.7, 3.0), cluster(), 0.2, 7);
    testing::random_velocities(fx.verts, 8, 1.0);
    const Hopper<2> h = make_hopper<2>(fx.c);
    DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
    ff.list().build(fx.verts, h);
    const auto terms = ff.terms();
    for (int k : {0, 1, 2, 3}) {  // shape terms and the contact: internal forces
      VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
      const TermOutput out = terms[k]->accumulate(fx.verts, f);
      Vec<2> total = Vec<2>::Zero();
      double torque = 0, scale = 0;
      for (int i = 0; i < fx.verts.size(); ++i) {
        total += f[i];
        torque += fx.verts.x[i][0] * f[i][1] - fx.verts.x[i][1] * f[i][0];
        scale += f[i].norm();
      }
      ASSERT_GT(scale, 0) << model << " " << terms[k]->name();
      EXPECT_LT(total.norm(), 1e-11 * scale) << model << " " << terms[k]->name();
      if (k < 3) {
        EXPECT_LT(std::fabs(torque), 1e-10 * scale) << model << " " << terms[k]->name();
      }
      if (k == 3) {
        EXPECT_LT(out.power, 0) << model << ": friction must remove energy";
        VecArray<2> fr;
        ff.friction_forces(fx.verts, fr);
        double power = 0;
        Vec<2> net = Vec<2>::Zero();
        for (int i = 0; i < fx.verts.size(); ++i) {
          power += fr[i].dot(fx.verts.v[i]);
          net += fr[i];
        }
        EXPECT_NEAR(power, out.power, 1e-9 * std::fabs(out.power)) << model;
        EXPECT_LT(net.norm(), 1e-11 * scale) << model;
      }
    }
    VecArray<2> fd(fx.verts.size(), Vec<2>::Zero());
    EXPECT_LT(terms[6]->accumulate(fx.verts, fd).power, 0) << model << ": drag";
  }
}

TEST(DpForces, ShapeEnergiesAreInvariantUnderRigidMotionAndZeroForReferencePolygons) {
  DpFixture fx(dp_config("dp_smooth", 2), {{-3, 4}, {3, 4}}, 0.25, 9);
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  auto shape_energy = [&](const ParticleState<2>& s) {
    double e = 0;
    for (int k = 0; k < 3; ++k) {
      VecArray<2> f(s.size(), Vec<2>::Zero());
      e += ff.terms()[k]->accumulate(s, f).energy;
    }
    return e;
  };
  const double e0 = shape_energy(fx.verts);
  ASSERT_GT(e0, 0);
  ParticleState<2> moved = fx.verts;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (auto& x : moved.x) x = Vec<2>(c * x[0] - s * x[1] + 1.3, s * x[0] + c * x[1] - 0.4);
  EXPECT_NEAR(shape_energy(moved), e0, 1e-10 * e0);
  // reference polygons: no area or segment energy; bending sum |u_i - u_i+1|^2 = n (2 sin(pi/n))^2
  DpFixture regular(dp_config("dp_smooth", 2), {{-3, 4}, {3, 4}}, 0.0, 9);
  double parts[3];
  for (int k = 0; k < 3; ++k) {
    VecArray<2> f(regular.verts.size(), Vec<2>::Zero());
    parts[k] = ff.terms()[k]->accumulate(regular.verts, f).energy;
  }
  EXPECT_LT(parts[0] + parts[1], 1e-20);
  const double n = regular.c.dp.n_v, turn = std::pow(2 * std::sin(units::pi / n), 2);
  double bending = 0;
  for (int m = 0; m < 2; ++m) bending += regular.c.dp.K_b / (2 * n * std::pow(regular.shape.l0[m], 2)) * n * turn;
  EXPECT_NEAR(parts[2], bending, 1e-12 * bending);
  EXPECT_NEAR(polygon_area(regular.poly, regular.verts.x, 1), regular.shape.a0[1], 1e-12);
}

/// The cluster, a polygon with an edge on the orifice's corner (the corner term acts), and
/// polygon 0 folded back at vertex 1 (the fold pairs act), with random velocities.
/// extra: polygons after the corner's, far from everything (so that the corner's polygon is
/// not the last, e.g. inside a group of four of the shape pass's lanes).
std::unique_ptr<DpFixture> corner_and_fold_fixture(const char* model, int extra = 0) {
  std::vector<Vec<2>> centres = cluster();
  const int m = int(centres.size());
  centres.push_back({1.5, 0.6});  // moved onto the orifice corner below
  for (int k = 0; k < extra; ++k) centres.push_back({-3.0 + 2.0 * k, 6.5});
  SimConfig c = dp_config(model, int(centres.size()), 0.4, 1.5);
  use_authors_dp_set(c);
  c.resolve_and_validate();
  auto made = std::make_unique<DpFixture>(c, centres, 0.2, 17);
  DpFixture& fx = *made;
  const int a = fx.poly.first[m], b = fx.poly.next[a];
  const Vec<2> e = fx.verts.x[b] - fx.verts.x[a];
  const Vec<2> outward = Vec<2>(e[1], -e[0]).normalized();
  const Vec<2> shift = Vec<2>(0.5 * c.w, 0) - 0.5 * (fx.verts.x[a] + fx.verts.x[b]) - 0.02 * fx.shape.l0[1] * outward;
  for (int i = fx.poly.first[m]; i < fx.poly.first[m + 1]; ++i) fx.verts.x[i] += shift;
  // polygon 0 folded back at vertex 1: vertex 2 lies beside edge 0 -> 1, 0.05 l0 off its line
  // and inside its slab, so the fold pairs at vertex 1 act
  {
    const int v0 = fx.poly.first[0], v1 = v0 + 1, v2 = v0 + 2;
    const Vec<2> e = fx.verts.x[v1] - fx.verts.x[v0];
    const Vec<2> inward = Vec<2>(-e[1], e[0]).normalized();
    fx.verts.x[v2] = fx.verts.x[v0] + 0.6 * e + 0.05 * fx.shape.l0[0] * inward;
  }
  Rng rng(5);
  for (auto& v : fx.verts.v) v = Vec<2>(rng.uniform(-1, 1), rng.uniform(-1, 1));
  return made;
}

// DpForceField::compute runs the shape terms polygon by polygon over edges measured once, the
// orifice corners only on the edges near them and the smooth contact's fold pairs only at the
// vertices where a polygon folds (found in the same pass); each vertex must still sum the same numbers
// in the same order as the terms one after another, so the forces and energies are equal bit
// for bit (the results of every DP job rest on this).
TEST(DpForces, FusedShapePassEqualsTheTermsOneAfterAnother) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    const std::unique_ptr<DpFixture> made = corner_and_fold_fixture(model);
    DpFixture& fx = *made;
    const Hopper<2> h = make_hopper<2>(fx.c);
    DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
    ParticleState<2> fused = fx.verts;
    const ForceReport r = ff.compute(fused);
    // the same terms one after another, in compute()'s order (terms(): area, segments, bending,
    // contact, walls, gravity, drag, corners, then the rough model's core and fold barrier)
    const std::vector<ForceTerm<2>*> t = ff.terms();
    std::vector<int> order = {0, 1, 2, 3};
    if (t.size() > 8) order.insert(order.end(), {8, 9});
    order.insert(order.end(), {4, 7, 5, 6});
    VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
    std::vector<double> energy(t.size());
    for (int k : order) energy[k] = t[k]->accumulate(fx.verts, f).energy;
    EXPECT_GT(energy[7], 0) << model << ": the corner term must act in this test";
    for (int i = 0; i < fx.verts.size(); ++i) {
      ASSERT_EQ(f[i][0], fused.f[i][0]) << model << " vertex " << i;
      ASSERT_EQ(f[i][1], fused.f[i][1]) << model << " vertex " << i;
    }
    EXPECT_EQ(r.U_shape, energy[0] + energy[1] + energy[2]) << model;
    EXPECT_EQ(r.U_wall, energy[4] + energy[7]) << model;
  }
}

// The shape pass takes four polygons at once in AVX2 lanes where the processor has AVX2
// (avx2::ShapeLanes), one at a time otherwise; both must give the same forces and energies bit
// for bit, with the fold and the orifice corner inside a group of four and in the tail.
TEST(DpForces, ShapeLanesEqualOnePolygonAtATime) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    for (const int extra : {0, 3}) {  // the corner's polygon last (the tail), or inside a group
      const std::unique_ptr<DpFixture> made = corner_and_fold_fixture(model, extra);
      DpFixture& fx = *made;
      const Hopper<2> h = make_hopper<2>(fx.c);
      DpForceField lanes(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c), one(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
      lanes.set_shape_lanes(true);
      one.set_shape_lanes(false);
      if (!lanes.shape_lanes()) GTEST_SKIP() << "no AVX2 on this processor: only the one-at-a-time path runs";
      ParticleState<2> a = fx.verts, b = fx.verts;
      const ForceReport ra = lanes.compute(a), rb = one.compute(b);
      EXPECT_GT(ra.U_wall, 0) << model << ": the corner must act";
      for (int i = 0; i < fx.verts.size(); ++i) {
        ASSERT_EQ(a.f[i][0], b.f[i][0]) << model << " extra " << extra << " vertex " << i;
        ASSERT_EQ(a.f[i][1], b.f[i][1]) << model << " extra " << extra << " vertex " << i;
      }
      EXPECT_EQ(ra.U_shape, rb.U_shape) << model;
      EXPECT_EQ(ra.U_contact, rb.U_contact) << model;
      EXPECT_EQ(ra.U_wall, rb.U_wall) << model;
      EXPECT_EQ(ra.max_overlap, rb.max_overlap) << model;
    }
  }
}

// DpModel::step takes velocity Verlet's closing kick in the force field's last sweep
// (compute_and_kick): the vertices an orifice corner touches wait for the corners. Forces and
// velocities must be the bits of compute() followed by kick(), with gravity and drag on, at one
// thread and at two; it sums no energies, and compute() after it still does.
TEST(DpForces, ComputeAndKickEqualsComputeThenKick) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    for (const int threads : {1, 2}) {
      const std::unique_ptr<DpFixture> made = corner_and_fold_fixture(model);
      DpFixture& fx = *made;
      ASSERT_GT(fx.c.drag_rate + fx.c.zeta, 0) << "drag must act in this test";
      const Hopper<2> h = make_hopper<2>(fx.c);
      const double dt = 1e-3;
      DpForceField apart_ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c), fused_ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
      apart_ff.set_threads(threads);
      fused_ff.set_threads(threads);
      ParticleState<2> apart = fx.verts, fused = fx.verts;
      const ForceReport ra = apart_ff.compute(apart);
      const bool finite_apart = kick(apart, dt, threads);
      bool finite_fused = false;
      const ForceReport rf = fused_ff.compute_and_kick(fused, dt, finite_fused);
      EXPECT_TRUE(finite_apart);
      EXPECT_TRUE(finite_fused);
      EXPECT_GT(ra.U_wall, 0) << model << ": the walls and corners must act in this test";
      for (int i = 0; i < fx.verts.size(); ++i) {
        ASSERT_EQ(apart.f[i][0], fused.f[i][0]) << model << " vertex " << i;
        ASSERT_EQ(apart.f[i][1], fused.f[i][1]) << model << " vertex " << i;
        ASSERT_EQ(apart.v[i][0], fused.v[i][0]) << model << " vertex " << i;
        ASSERT_EQ(apart.v[i][1], fused.v[i][1]) << model << " vertex " << i;
      }
      EXPECT_EQ(ra.max_overlap, rf.max_overlap);
      EXPECT_GT(rf.max_overlap, 0) << model << ": contacts must act in this test";
      EXPECT_EQ(rf.potential(), 0) << "the fused step sums no energies";
      // and compute() on the same field afterwards still sums them all
      ParticleState<2> again = fx.verts;
      const ForceReport rc = fused_ff.compute(again);
      EXPECT_EQ(ra.U_shape, rc.U_shape);
      EXPECT_EQ(ra.U_contact, rc.U_contact);
      EXPECT_EQ(ra.U_wall, rc.U_wall);
      EXPECT_EQ(ra.U_gravity, rc.U_gravity);
      EXPECT_EQ(ra.P_drag, rc.P_drag);
      EXPECT_EQ(ra.P_friction, rc.P_friction);
      // a velocity made infinite is reported
      ParticleState<2> bad = fx.verts;
      bad.v[3][0] = INFINITY;
      bool finite_bad = true;
      fused_ff.compute_and_kick(bad, dt, finite_bad);
      EXPECT_FALSE(finite_bad) << model;
    }
  }
}

TEST(DpForces, SmoothConcaveCornerIsContinuousAndCountedOnce) {
  // Polygon 0 dented at vertex 3 (a concave corner), vertex j of polygon 1 travelling along
  // edge 2 -> 3 at 0.6 delta outside it, into and across the slab of edge 3 -> 4. Near the
  // corner j is in both slabs; the corner's energy is taken away once there, so nothing jumps
  // where j enters the second slab or leaves the first (the wedge rule alone dropped or added
  // a slab's energy there: jumps of 18 % and 80 % of the contact's scale, seen 2026-12-04).
  CornerProbe probe;
  const SimConfig& c = probe.c;
  DpFixture& fx = probe.fx;
  auto& x = fx.verts.x;
  const int corner = probe.corner;
  x[corner] += 0.6 * fx.shape.l0[0] * (Vec<2>(0.0, 3.0) - x[corner]).normalized();
  const Vec<2> r = x[corner];
  const Vec<2> e_in = (r - x[fx.poly.prev[corner]]).normalized(), e_out = (x[fx.poly.next[corner]] - r).normalized();
  ASSERT_LT(e_in[0] * e_out[1] - e_in[1] * e_out[0], 0) << "the corner is not concave";
  const Vec<2> n_in(e_in[1], -e_in[0]);
  const double delta = 0.5 * (fx.shape.delta[0] + fx.shape.delta[1]), gap = 0.6 * delta;
  const double scale = 0.5 * c.dp.E_c * 0.4 * 0.4;  // one slab's energy at this gap
  std::vector<double> on_polygon0;
  for (int k = -30; k <= 10; ++k) {
    const Vec<2> pos = r + gap * n_in + (0.005 * k * fx.shape.l0[0]) * e_in;
    const double total = probe.contact_energy(pos, n_in);
    EXPECT_NEAR(total, brute_force_smooth_energy(fx, c.dp.E_c), 1e-9 * scale) << "step " << k;
    on_polygon0.push_back(brute_force_smooth_energy(fx, c.dp.E_c, /*edges_of=*/0));
    if (k == -5) {  // in both slabs: the forces are the energy's gradient there too
      DpFixture here = fx;
      check_gradients(here, 1);
    }
  }
  EXPECT_GT(on_polygon0.back(), 2 * scale);  // the path did reach deep into the corner
  for (std::size_t k = 1; k + 1 < on_polygon0.size(); ++k)  // smooth: small second differences
    EXPECT_LT(std::fabs(on_polygon0[k + 1] - 2 * on_polygon0[k] + on_polygon0[k - 1]), 0.05 * scale)
        << "jump near step " << int(k) - 30;
}

}  // namespace
}  // namespace beverloo
