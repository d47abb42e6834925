#pragma once
/// \file dp_system.h
/// \brief The vertex-level half of a DP hopper run: polygons, vertex state and force field.
///
/// The protocol (exits, reinjection, pile, observables, flow rate) works on one body per
/// polygon, exactly as for SP particles: HopperRun keeps a per-particle state whose position
/// is the polygon's centroid and whose velocity is the mean vertex velocity (the polygon's
/// centre-of-mass velocity, vertex masses being equal). DpSystem keeps the two in step.
#include <memory>

#include "../geometry/hopper.h"
#include "../integrate/fire.h"
#include "../rng.h"
#include "dp_force_field.h"
#include "polygons.h"

namespace beverloo {

class DpSystem {
 public:
  DpSystem(const SimConfig& c, const Hopper<2>& hopper);

  /// Species of the bodies (centroids): sigma is the bounding diameter of a reference polygon
  /// with its contact shell, widened by `kBodyMargin` so that the pile's connectivity (bodies
  /// overlapping) survives moderate deformation; masses and reference areas as for SP.
  Species body_species() const;
  /// Jittered triangular lattice above the funnel with shuffled species: polygons start
  /// without any overlap (random overlapping disks, as for SP, would leave polygons inside
  /// one another, which no contact force can undo).
  void place_bodies(ParticleState<2>& bodies, Rng& rng) const;
  /// Regular reference polygons at the bodies' positions, random orientations, at rest.
  void build_polygons(const ParticleState<2>& bodies, Rng& rng);
  /// FIRE on the polygons with gravity and dissipation off and E_c softened to
  /// fire.max_pair_stiffness (as for SP).
  FireResult minimize(const FireParams& p, double dt);
  /// bodies.x = centroids, bodies.v = mean vertex velocities.
  void sync_bodies(ParticleState<2>& bodies) const;
  /// The step's first half on one thread, in one pass over the vertices: drift() of every
  /// vertex (velocity_verlet.h), then sync_bodies() of the drifted vertices, each the very
  /// operations of the two one after the other (the same bits: DpSystem tests compare them);
  /// and the largest squared displacement from `reference` (the list's build positions; of
  /// another size: not measured, -1 returned). The vertex arrays are larger than the cache,
  /// and these were three sweeps over them (the list's test the third).
  double drift_and_sync(ParticleState<2>& bodies, double dt, const VecArray<2>& reference);
  /// Polygon m becomes a regular reference polygon at `centre` moving with `velocity`.
  void reinject(int m, const Vec<2>& centre, const Vec<2>& velocity, double angle);
  /// Takes polygon m out (a draining hopper): the last polygon's vertices take its place.
  void remove_polygon(int m);
  /// Keeps the first n polygons (a checkpoint of a draining hopper holds fewer than N).
  void keep_polygons(int n);
  /// True if polygon m, placed at `centre` in any orientation, would touch no edge or vertex
  /// of another polygon. O(vertices); called for reinjection candidates only.
  bool spot_is_free(int m, const Vec<2>& centre) const;
  /// Friction force on each body: the sum over its vertices.
  void body_friction(VecArray<2>& out);
  /// Throws InstabilityError if an edge outgrew the contact list's reach, a vertex left the
  /// container sideways, or a polygon edge cuts a funnel wall (the polygon went through it).
  void check_vertices(double t) const;

  ParticleState<2>& verts() { return verts_; }
  const ParticleState<2>& verts() const { return verts_; }
  DpForceField& forces() { return *ff_; }
  const DpForceField& forces() const { return *ff_; }
  const PolygonSet& polygons() const { return poly_; }
  const DpShape& shape() const { return shape_; }

  static constexpr double kBodyMargin = 1.1;
  /// An edge longer than this many l0 (large species) stops the run: the polygon is tearing.
  static constexpr double kMaxEdgeStretch = 8.0;

 private:
  /// bodies.x, bodies.v: each polygon's vertex sums over n_v, four polygons side by side (eight
  /// independent chains), each summed in its vertex order. vertex(i, x, v) gives vertex i's
  /// position and velocity (sync_bodies: as stored; drift_and_sync: drifted first).
  template <class Vertex>
  void sum_polygons(ParticleState<2>& bodies, Vertex&& vertex) const;
  SimConfig c_;
  const Hopper<2>& hopper_;
  DpShape shape_;
  PolygonSet poly_;
  ParticleState<2> verts_;
  std::unique_ptr<DpForceField> ff_;
  VecArray<2> vertex_scratch_;
};

}  // namespace beverloo
