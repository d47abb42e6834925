#pragma once
/// \file dp_polygon_edges.h
/// \brief The edge vectors and lengths of one polygon, measured once per force evaluation and
/// shared by the shape terms that need them (segment length, bending): DpForceField's pass over
/// the polygons takes one square root per edge where the terms alone take one each.
#include <cmath>
#include <vector>

#include "../dp/polygons.h"
#include "../vec.h"

namespace beverloo {

struct PolygonEdges {
  int first = 0;            ///< the polygon's first vertex; edge k runs from vertex first + k to its next
  int count = 0;            ///< its edges (= vertices)
  VecArray<2> e;            ///< edge vectors r_next(i) - r_i
  std::vector<double> sq;   ///< |e_k|^2 (Eigen's squaredNorm())
  std::vector<double> len;  ///< |e_k| = sqrt(|e_k|^2), as Eigen's norm() computes it (the terms' own bits)
  // bending's scratch for the same polygon (one PolygonEdges per thread's share of polygons)
  VecArray<2> unit;             ///< e_k / |e_k|
  std::vector<double> inv_len;  ///< 1 / |e_k|

  /// Measures polygon m. Allocates only when a polygon has more vertices than any before.
  void measure(const PolygonSet& p, const VecArray<2>& x, int m) {
    first = p.first[m];
    const int n = count = p.first[m + 1] - first;
    if (static_cast<int>(e.size()) < n) {
      e.resize(n);
      sq.resize(n);
      len.resize(n);
      unit.resize(n);
      inv_len.resize(n);
    }
    for (int k = 0; k < n; ++k) {
      const int i = first + k;
      e[k] = x[p.next[i]] - x[i];
      sq[k] = e[k].squaredNorm();
      len[k] = std::sqrt(sq[k]);
    }
  }
};

}  // namespace beverloo
