#pragma once
/// \file dp_force_field.h
/// \brief All force terms of a DP simulation over the vertex state: the three shape terms,
/// the contact of the chosen variant (smooth: circulo-line edges; rough: vertex disks, which
/// is the SP contact over vertices with pairs inside one polygon excluded), per-vertex walls,
/// gravity, drag zeta/n_v. Same interface as ForceField, so the integrator, FIRE and the
/// generic physics tests take either.
#include <memory>
#include <string>
#include <optional>
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
#include "../forces/parallel_chunks.h"
#include "../forces/sp_contact.h"
#include "../geometry/funnel_cores.h"
#include "dp_shape_lanes_avx2.h"
#include "polygons.h"

namespace beverloo {

class DpForceField {
 public:
  /// E_c overrides c.dp.E_c when given (FIRE removes overlaps with a softer contact).
  DpForceField(const SimConfig& c, const Hopper<2>& hopper, const PolygonSet& p, const DpShape& shape,
               double E_c);

  /// Zeroes s.f, brings the vertex list up to date and adds every term. O(vertices).
  ForceReport compute(ParticleState<2>& s);
  /// compute(), then velocity Verlet's closing kick v += f dt / (2 m) (kick_one of
  /// sp_sweeps.h), the kick taken in the same sweep as the last vertex terms (walls, gravity,
  /// drag) instead of a sweep of its own: each vertex is kicked once its force is complete, so
  /// the forces and velocities are the bits of compute() followed by kick()
  /// (DpForces.ComputeAndKickEqualsComputeThenKick). finite: every position and velocity. The
  /// report holds max_overlap and no energies or powers (as SP's fused step): their running sums
  /// are chains of dependent adds through every vertex, and a flow step needs none of them
  /// (compute() has them, for the same forces).
  /// max_moved2: the largest squared displacement of a vertex from the list's reference
  /// positions, measured in the step's drift pass (DpSystem::drift_and_sync), so that the
  /// list's rebuild test needs no sweep of its own; without it the list measures. When the list
  /// rebuilds changes no force (the rows are sorted and hold every pair in reach either way).
  ForceReport compute_and_kick(ParticleState<2>& s, double dt, bool& finite,
                               std::optional<double> max_moved2 = std::nullopt);
  /// OpenMP threads for the evaluation: the shape terms by polygons, walls, gravity and drag
  /// by vertices, the smooth contact and the rough model's edge core by list rows (their force
  /// writes replayed in order); the rough disks and the fold pairs on one thread. Work
  /// is cut into fixed chunks whatever the count and every sum is taken chunk by chunk in
  /// chunk order, so every count gives the same forces and energies, bit for bit.
  void set_threads(int threads);
  /// The shape pass four polygons at a time in AVX2 lanes (the default where the processor has
  /// AVX2) or one at a time: the same bits either way (tests compare them).
  void set_shape_lanes(bool on);
  bool shape_lanes() const { return lanes_; }
  int threads() const { return threads_; }
  static constexpr int kPolygonsPerChunk = 64;
  static constexpr int kVerticesPerChunk = 1024;
  void set_dissipation(bool on);
  void set_gravity(double g) { gravity_.set_g(g); }
  NeighborList<2>& list() { return list_; }
  /// Kinetic-friction force on each vertex alone; overwrites out.
  void friction_forces(const ParticleState<2>& s, VecArray<2>& out) const;
  /// Longest edge at the last evaluation.
  double longest_edge() const { return segments_.longest_edge(); }
  /// The length up to which edge i is searched for contacts of the smooth edges or the rough
  /// edge core, from the nearer of its end vertices: vertex i's list reach covers the edge
  /// width and half the longer of its two edges' bounds (edge_reach(); for rough vertex disks,
  /// only what that exceeds the disk's reach). Bounds are set to kEdgeBoundGrowth times the edge's
  /// length (at least kEdgeBoundFloor l0) whenever some edge outgrows its bound; only the
  /// list's reach depends on them, not the forces, so any history of them gives bit-identical
  /// forces.
  double edge_bound(int edge) const { return edge_bound_[edge]; }
  static constexpr double kEdgeBoundGrowth = 1.25;
  static constexpr double kEdgeBoundFloor = 1.25;
  /// area, segment length, bending, contact, walls, gravity, drag, wall corners (rough: and
  /// the edge core, and the fold barrier)
  std::vector<ForceTerm<2>*> terms();
  /// Where the largest contact overlap of the last evaluation is (for failure messages).
  std::string describe_worst_contact(const ParticleState<2>& s, const PolygonSet& p) const;

  /// The funnel walls' cores (dp.wall_thickness; half_thickness() 0: walls are lines).
  const FunnelCores& funnel_cores() const { return cores_; }
  /// Vertex "diameters" for the Verlet list: the contact diameters; the smooth contact adds
  /// each vertex's edge reach on top (NeighborList::set_extra_reach).
  static std::array<double, 2> list_diameters(const DpShape& shape);
  /// The polygons changed (one taken out): the edge bounds start again from their floor and the
  /// list is rebuilt (the list's contents never change a force sum, so no result depends on it).
  void topology_changed();

 private:
  /// The shape terms (area, segment length, bending) polygon by polygon over edges measured
  /// once; on the way, whether an edge outgrew its bound and which edges may touch an orifice
  /// corner (corner_edges_). Returns their energy, each term's sum in its own order.
  double shape_pass(ParticleState<2>& s, bool energies);
  /// shape_pass()'s work on polygon chunk c: its forces, and its results into shape_chunks_[c].
  void shape_chunk(ParticleState<2>& s, int c, bool energies);
  struct ShapeChunk;
  /// The same for polygons m .. m + 3 at once in AVX2 lanes (avx2::ShapeLanes), the same bits.
  void shape_four(ParticleState<2>& s, int m, ShapeChunk& ch, bool energies, double sums[3], double& longest,
                  bool& outgrown);
  avx2::ShapeConstants lane_constants_;  ///< set at construction
  bool lanes_ = false;                   ///< the shape pass runs four polygons at once (AVX2 here)
  /// Every edge's bound set again from its length, and the list invalidated (an edge outgrew its bound).
  void reset_edge_bounds(const ParticleState<2>& s);

  const DpShape& shape_;
  const PolygonSet& poly_;
  std::vector<double> edge_bound_;    ///< per edge i -> next(i)
  std::vector<double> vertex_reach_;  ///< per vertex: extra list reach for its two edges
  /// The edges' contact widths per species: the smooth edges' (shape.delta), the rough core's.
  std::array<double, 2> edge_widths_;
  /// The list reach a vertex needs beyond the pair diameter for edges up to 2 half_bound long.
  double edge_reach(double half_bound) const;
  NeighborList<2> list_;
  DpArea area_;
  DpSegmentLength segments_;
  DpBending bending_;
  std::unique_ptr<DpSmoothContact> smooth_;
  std::unique_ptr<SpContact<2>> rough_;
  std::unique_ptr<DpSmoothContact> rough_core_;
  std::unique_ptr<DpSmoothContact> rough_fold_;
  HopperWalls<2> walls_;
  Gravity<2> gravity_;
  Drag<2> drag_;
  DpWallCorners corners_;
  /// body(chunk) for chunks 0 .. count-1 on threads_ threads (parallel_chunks.h).
  template <class Body>
  void for_chunks(int count, Body&& body) const { for_each_chunk(threads_, count, body); }
  /// Everything before the vertex terms: the shape pass, the list, the contact.
  ForceReport shape_list_and_contact(ParticleState<2>& s, bool energies, std::optional<double> max_moved2 = std::nullopt);
  /// Walls, orifice corners, gravity and drag, vertex chunk by vertex chunk; with half_dt > 0
  /// also the kick of each vertex once its force is complete (returns whether every position
  /// and velocity is finite; without the kick: true).
  bool add_vertex_terms(ParticleState<2>& s, ForceReport& r, double half_dt, bool energies);

  const Hopper<2>& hopper_;
  FunnelCores cores_;             ///< the funnel walls' cores (thickness 0: unused)
  /// One chunk of kPolygonsPerChunk polygons in the shape pass: its scratch and its results.
  struct ShapeChunk {
    PolygonEdges edges;
    avx2::ShapeLanes lanes;  ///< four polygons at once (AVX2), the same bits
    double U_area = 0, U_length = 0, U_bending = 0, longest = 0;
    bool outgrown = false;
    std::vector<int> corner_edges, fold_vertices;
  };
  std::vector<ShapeChunk> shape_chunks_;
  std::vector<double> chunk_sums_;  ///< per vertex chunk: energies or powers of one term
  std::vector<int> chunk_bad_;      ///< per vertex chunk: a kicked position or velocity not finite
  /// per vertex: 1 while an orifice corner may still add to its force (its gravity, drag and
  /// kick wait for the corners); all 0 between evaluations
  std::vector<std::uint8_t> waits_for_corners_;
  int threads_ = 1;
  bool edge_outgrown_ = false;    ///< set by shape_pass
  std::vector<int> corner_edges_; ///< edges (start vertex) that may touch an orifice corner, increasing
  std::vector<int> fold_vertices_; ///< vertices at which the fold pairs (smooth contact, rough fold barrier) may act, increasing
};

}  // namespace beverloo
