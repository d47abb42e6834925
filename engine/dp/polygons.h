#pragma once
/// \file polygons.h
/// \brief The deformable particles of physics.md 4 as polygons over a flat vertex array.
///
/// Vertex storage is one ParticleState<2> over all vertices (structure of arrays, as for SP
/// particles), so the integrator, the Verlet list and the generic terms (gravity, drag, walls)
/// work on vertices unchanged. PolygonSet adds the topology: per-polygon offsets into the
/// vertex arrays, the owner of each vertex and precomputed cyclic neighbours, so no term ever
/// computes "(i + 1) % n_v". Vertices of a polygon are stored counter-clockwise, so the
/// shoelace area is positive and the outward normal of edge i -> next(i) is (e_y, -e_x)/|e|.
#include <vector>

#include "../config.h"
#include "../state.h"

namespace beverloo {

/// Reference shape and contact constants of the two species (0 = small, 1 = large).
struct DpShape {
  int n_v = 16;
  double a0[2]{};           ///< reference area pi sigma^2 / 4
  double l0[2]{};           ///< reference edge length of the regular polygon of area a0
  double delta[2]{};        ///< contact diameter: l0 (rough vertex disks) or dp.contact_width l0 (smooth edges)
  double wall[2]{};         ///< diameter against walls and orifice corners: dp.wall_width l0, unset: delta
  double wall_thickness = 0; ///< of the funnel walls: dp.wall_thickness l0 of the small species
  double vertex_mass[2]{};  ///< M / n_v
  double circumradius[2]{}; ///< of the regular reference polygon
  bool smooth = true;

  static DpShape from_config(const SimConfig& c);
  /// Diameter of the disk that surely contains a reference polygon and its contact shells
  /// (with each other and with the walls).
  double bounding_diameter(int species) const {
    return 2 * circumradius[species] + (wall[species] > delta[species] ? wall[species] : delta[species]);
  }
};

/// Topology of N polygons (vertex ranges, owners, cyclic neighbours).
struct PolygonSet {
  std::vector<int> first;  ///< polygon m owns vertices [first[m], first[m+1])
  std::vector<int> owner;  ///< polygon of each vertex
  std::vector<int> next;   ///< following vertex (counter-clockwise), cyclic within the polygon
  std::vector<int> prev;   ///< preceding vertex

  int polygons() const { return static_cast<int>(first.size()) - 1; }
  int vertices() const { return static_cast<int>(owner.size()); }
  /// n polygons of n_v vertices each.
  static PolygonSet uniform(int n, int n_v);
};

/// Signed (shoelace) area of polygon m: positive for counter-clockwise vertices.
double polygon_area(const PolygonSet& p, const VecArray<2>& x, int m);
/// Centre of mass of polygon m's vertices (equal vertex masses).
Vec<2> polygon_centroid(const PolygonSet& p, const VecArray<2>& x, int m);
/// Perimeter of polygon m.
double polygon_perimeter(const PolygonSet& p, const VecArray<2>& x, int m);
/// True if no two non-adjacent edges of polygon m intersect (O(n_v^2), for tests and checks).
bool polygon_is_simple(const PolygonSet& p, const VecArray<2>& x, int m);

/// Writes polygon m as the regular reference polygon of its species centred at `centre`,
/// first vertex at angle `angle`, all vertices moving with `velocity`.
void place_regular_polygon(const PolygonSet& p, const DpShape& shape, ParticleState<2>& verts, int m,
                           const Vec<2>& centre, double angle, const Vec<2>& velocity);

}  // namespace beverloo
