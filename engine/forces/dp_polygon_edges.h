#pragma once
/// \file dp_polygon_edges.h
/// \brief One polygon's positions, edge vectors and lengths as plain arrays (structure of
/// arrays), measured once per force evaluation and shared by the shape terms (area, segment
/// length, bending), with room for each term's per-edge results.
///
/// Why arrays: the shape terms are a third of a DP step and each edge needs a square root and
/// divisions. Over contiguous arrays, with the cyclic neighbours as a padding element on each
/// side (x[-1] is the last vertex, x[n] the first), every per-edge loop is a straight loop that
/// the compiler turns into SIMD instructions; each element still takes exactly the operations
/// (and roundings) of the scalar formula, so the forces are the same bits as one edge at a time.
/// A polygon's vertices are contiguous and cyclic (PolygonSet::uniform): vertex first + k is
/// followed by first + (k + 1) mod n.
#include <cmath>
#include <vector>

#include "../dp/polygons.h"
#include "../vec.h"

namespace beverloo {

class PolygonEdges {
 public:
  int first = 0;  ///< the polygon's first vertex; edge k runs from vertex first + k to its next
  int count = 0;  ///< its edges (= vertices)
  int species = 0;

  PolygonEdges() = default;
  // scratch: a copy starts empty (the pointers must never point into another's storage)
  PolygonEdges(const PolygonEdges&) {}
  PolygonEdges& operator=(const PolygonEdges&) { return *this; }

  // Every pointer below indexes k = 0 .. count-1; x, y, ux and uy also k = -1 and k = count
  // (the cyclic neighbours), ex, ey and sq also k = -1, where the producer wrote them.
  double* x = nullptr;   ///< positions
  double* y = nullptr;
  double* ex = nullptr;  ///< edge vectors r_next(k) - r_k
  double* ey = nullptr;
  double* sq = nullptr;  ///< |e_k|^2 = ex^2 + ey^2 (Eigen's squaredNorm())
  double* len = nullptr; ///< |e_k| = sqrt(|e_k|^2) (Eigen's norm())
  // per-term results for the fused pass and the terms' own scatter (DpArea, DpSegmentLength, DpBending)
  double* area_fx = nullptr;   ///< area force on vertex k
  double* area_fy = nullptr;
  double* seg_fx = nullptr;    ///< segment force on edge k's end vertex (its start takes minus it)
  double* seg_fy = nullptr;
  double* seg_u = nullptr;     ///< edge k's segment energy
  double* inv_len = nullptr;   ///< 1 / |e_k|
  double* ux = nullptr;        ///< e_k / |e_k|
  double* uy = nullptr;
  double* bend_dx = nullptr;   ///< dU_bending / de_k: pushes edge k's start, pulls its end
  double* bend_dy = nullptr;
  double* bend_u = nullptr;    ///< edge k's bending energy (with its next edge)

  /// Measures polygon m: positions, edge vectors, squared lengths and lengths. Allocates only
  /// when a polygon has more vertices than any before.
  void measure(const PolygonSet& p, const ParticleState<2>& s, int m) {
    first = p.first[m];
    const int n = count = p.first[m + 1] - first;
    species = s.species[first];  // one species per polygon
    if (n > capacity_) allocate(n);
    const Vec<2>* r = s.x.data() + first;
    double* __restrict px = x;
    double* __restrict py = y;
    for (int k = 0; k < n; ++k) {
      px[k] = r[k][0];
      py[k] = r[k][1];
    }
    px[-1] = px[n - 1];
    py[-1] = py[n - 1];
    px[n] = px[0];
    py[n] = py[0];
    double* __restrict dx = ex;
    double* __restrict dy = ey;
    double* __restrict q = sq;
    double* __restrict l = len;
    #pragma omp simd  // element-wise: the same operations per edge as the scalar loop
    for (int k = 0; k < n; ++k) {
      dx[k] = px[k + 1] - px[k];
      dy[k] = py[k + 1] - py[k];
      q[k] = dx[k] * dx[k] + dy[k] * dy[k];
      l[k] = std::sqrt(q[k]);
    }
    dx[-1] = dx[n - 1];  // edge -1 is the last: the edge into vertex 0
    dy[-1] = dy[n - 1];
    q[-1] = q[n - 1];
  }
  /// e_a . e_b (Eigen's dot()).
  double dot(int a, int b) const { return ex[a] * ex[b] + ey[a] * ey[b]; }

 private:
  static constexpr int kArrays = 17;
  std::vector<double> storage_;
  int capacity_ = 0;
  void allocate(int n) {
    capacity_ = n;
    const int stride = n + 2;  // one pad on each side
    storage_.assign(std::size_t(kArrays) * stride, 0.0);
    double** arrays[kArrays] = {&x, &y, &ex, &ey, &sq, &len, &area_fx, &area_fy, &seg_fx,
                                &seg_fy, &seg_u, &inv_len, &ux, &uy, &bend_dx, &bend_dy, &bend_u};
    for (int a = 0; a < kArrays; ++a) *arrays[a] = storage_.data() + std::size_t(a) * stride + 1;
  }
};

}  // namespace beverloo
