#pragma once
/// \file dp_wall_corners.h
/// \brief The orifice corners against polygon edges (both DP variants).
///
/// Walls act on vertices (physics.md 4), which is enough for flat walls: a polygon cannot
/// cross a flat wall without one of its vertices crossing it. A convex wall corner (the two
/// orifice edges) is a point, and it can slip between two vertices of a smooth polygon, whose
/// edges are thin circulo-lines (width 0.1 l0): seen as polygons impaled on the corner and
/// pulled under the floor. So each corner also repels every edge whose slab it lies in, with
/// the wall's form U = (E_w/2)(1 - 2 d/delta_m)^2 for the perpendicular distance d < delta_m/2,
/// the force on the edge split between its end vertices by the lever rule. The edge's width
/// is the smooth model's 0.1 l0 in both variants: rough polygons' vertex disks (diameter l0)
/// close the gaps while edges keep their length, but a stretched edge of a soft rough polygon
/// opens one (seen: K_l = 1), and this thin core only acts once the corner is that deep.
#include <array>
#include <cmath>
#include <vector>

#include "../dp/polygons.h"
#include "../geometry/funnel_cores.h"
#include "../geometry/hopper.h"
#include "force_term.h"
#include "harmonic_overlap.h"

namespace beverloo {

class DpWallCorners final : public ForceTerm<2> {
 public:
  DpWallCorners(const Hopper<2>& hopper, const PolygonSet& p, const DpShape& shape, double E_w)
      : p_(p), shape_(shape), eps_(E_w) {
    const double half = hopper.orifice_half_width();
    corners_ = {Vec<2>(-half, 0.0), Vec<2>(half, 0.0)};
  }
  /// Funnel walls with a thickness (dp.wall_thickness): each corner is the lip's bead, a disk of
  /// radius T/2 at the core's start, and an edge feels its surface, d - T/2 (the same form).
  void set_funnel_cores(const FunnelCores& cores) {
    corners_ = {cores.lip_centre(0), cores.lip_centre(1)};
    lip_radius_ = cores.half_thickness();
  }
  std::string_view name() const override { return "dp_wall_corners"; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    double energy = 0;
    const int nv = p_.vertices();
    for (int i = 0; i < nv; ++i) edge_against_corners(s, f, i, energy);
    return {energy, 0};
  }
  /// The same for the listed edges only (by their start vertex, increasing): DpForceField lists
  /// those for which may_touch() holds while it measures the edges for the shape terms, so the
  /// edges far from the orifice cost nothing here; the sum is accumulate()'s, bit for bit.
  TermOutput accumulate_edges(const ParticleState<2>& s, VecArray<2>& f, const std::vector<int>& edges) const {
    double energy = 0;
    for (const int i : edges) edge_against_corners(s, f, i, energy);
    return {energy, 0};
  }
  /// False if no edge of a polygon with vertex `any` and perimeter `perimeter` can touch a corner:
  /// an edge's start vertex is within half the perimeter of `any`, and a corner it touches within
  /// its length (at most half the perimeter) plus half_delta of that start.
  bool polygon_may_touch(const ParticleState<2>& s, int any, double perimeter) const {
    const double reach = perimeter + half_width(1) + half_width(0) + lip_radius_;
    for (const Vec<2>& c : corners_)
      if ((c - s.x[any]).squaredNorm() < reach * reach) return true;
    return false;
  }
  /// False if the edge from vertex i (squared length e2) is surely out of both corners' reach:
  /// a corner in its slab within half_delta of its line is within sqrt(|e|^2 + half_delta^2) of r_i.
  bool may_touch(const ParticleState<2>& s, int i, double e2) const {
    const double reach = half_width(s.species[i]) + lip_radius_;
    for (const Vec<2>& c : corners_)
      if ((c - s.x[i]).squaredNorm() < e2 + reach * reach) return true;
    return false;
  }

 private:
  const PolygonSet& p_;
  const DpShape& shape_;
  double eps_;
  std::array<Vec<2>, 2> corners_;
  double lip_radius_ = 0;  ///< 0: the corners are points (walls are lines)

  double half_width(int species) const { return 0.05 * shape_.l0[species]; }
  void edge_against_corners(const ParticleState<2>& s, VecArray<2>& f, int i, double& energy) const {
    const int j = p_.next[i];
    const Vec<2> e = s.x[j] - s.x[i];
    const double e2 = e.squaredNorm();
    const double half_delta = half_width(s.species[i]);
    for (const Vec<2>& c : corners_) {
      const Vec<2> q = c - s.x[i];
      // in the slab (0 <= t <= 1) and within half_delta of the line: |q|^2 <= |e|^2 + half_delta^2,
      // whatever the edge's length (soft edges stretch to several l0)
      const double reach = half_delta + lip_radius_;
      if (q.squaredNorm() >= e2 + reach * reach) continue;
      const double t = q.dot(e) / e2;
      if (t < 0 || t > 1) continue;  // beyond the ends: the vertices' own wall contact
      const double len = std::sqrt(e2);
      const Vec<2> n(e[1] / len, -e[0] / len);  // outward normal
      // corner outside the polygon: d > 0; a lip's surface (radius lip_radius_), not its centre
      const double d = q.dot(n) - lip_radius_;
      if (d >= half_delta || d <= -half_delta - 2 * lip_radius_) continue;
      double dU_dd;
      energy += HarmonicOverlap::energy(eps_, d, 1.0 / half_delta, dU_dd);
      // dd/dr_i = -(1 - t) n, dd/dr_j = -t n (the corner is fixed)
      f[i] += (dU_dd * (1 - t)) * n;
      f[j] += (dU_dd * t) * n;
    }
  }
};

}  // namespace beverloo
