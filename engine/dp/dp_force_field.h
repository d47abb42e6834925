#pragma once
/// \file dp_force_field.h
/// \brief All force terms of a DP simulation over the vertex state: the three shape terms,
/// the contact of the chosen variant (smooth: circulo-line edges; rough: vertex disks, which
/// is the SP contact over vertices with pairs inside one polygon excluded), per-vertex walls,
/// gravity, drag zeta/n_v. Same interface as ForceField, so the integrator, FIRE and the
/// generic physics tests take either.
#include <memory>
#include <string>
#include <vector>

#include "../config.h"
#include "../forces/dp_area.h"
#include "../forces/dp_bending.h"
#include "../forces/dp_segment_length.h"
#include "../forces/dp_smooth_contact.h"
#include "../forces/dp_wall_corners.h"
#include "../forces/drag.h"
#include "../forces/force_field.h"
#include "../forces/gravity.h"
#include "../forces/hopper_walls.h"
#include "../forces/sp_contact.h"
#include "polygons.h"

namespace beverloo {

class DpForceField {
 public:
  /// E_c overrides c.dp.E_c when given (FIRE removes overlaps with a softer contact).
  DpForceField(const SimConfig& c, const Hopper<2>& hopper, const PolygonSet& p, const DpShape& shape,
               double E_c);

  /// Zeroes s.f, brings the vertex list up to date and adds every term. O(vertices).
  ForceReport compute(ParticleState<2>& s);
  void set_dissipation(bool on);
  void set_gravity(double g) { gravity_.set_g(g); }
  NeighborList<2>& list() { return list_; }
  /// Kinetic-friction force on each vertex alone; overwrites out.
  void friction_forces(const ParticleState<2>& s, VecArray<2>& out) const;
  /// Longest edge at the last evaluation (bounds the smooth contact's reach).
  double longest_edge() const { return segments_.longest_edge(); }
  /// The longest edge the smooth contact search covers now: shape.max_edge, grown (never
  /// shrunk) whenever an edge stretches beyond it. Only the list's reach depends on it, not
  /// the forces, so runs with different histories of it stay bit-identical.
  double edge_reach() const { return edge_reach_; }
  /// area, segment length, bending, contact, walls, gravity, drag, wall corners
  std::vector<ForceTerm<2>*> terms();
  /// Where the largest contact overlap of the last evaluation is (for failure messages).
  std::string describe_worst_contact(const ParticleState<2>& s, const PolygonSet& p) const;

  /// Vertex "diameters" for the Verlet list: its reach must cover every contact.
  static std::array<double, 2> list_diameters(const DpShape& shape);

 private:
  const DpShape& shape_;
  double edge_reach_;
  NeighborList<2> list_;
  DpArea area_;
  DpSegmentLength segments_;
  DpBending bending_;
  std::unique_ptr<DpSmoothContact> smooth_;
  std::unique_ptr<SpContact<2>> rough_;
  HopperWalls<2> walls_;
  Gravity<2> gravity_;
  Drag<2> drag_;
  DpWallCorners corners_;
  const Hopper<2>& hopper_;
};

}  // namespace beverloo
