#pragma once
/// \file dp_shape_lanes_avx2.h
/// \brief The DP shape terms (area, segment length, bending) of four polygons at once, one
/// polygon per AVX2 lane, with the very operations of the per-polygon code (PolygonEdges and
/// DpArea::vertex_forces, DpSegmentLength::edge_forces, DpBending::edge_gradients,
/// write_shape_forces in dp_force_field.cpp): every lane takes its polygon's operations in their
/// order, so the forces are the same bits as one polygon at a time
/// (DpForces.FusedShapePassEqualsTheTermsOneAfterAnother, bench/result_identity.sh).
///
/// Why lanes of polygons rather than of edges: a polygon has 16 edges, so 4-wide loops over one
/// polygon's edges were mostly prologue and epilogue (measured 0.8 times as fast), and its area
/// is a sum in edge order, a chain of dependent adds; four polygons side by side run four such
/// chains at once and every loop is full width. The build is -O3 -ffp-contract=off without FMA
/// in the target, so no multiply and add are fused here either.
#include <immintrin.h>

#include <vector>

namespace beverloo::avx2 {

/// The per-species constants of the shape terms (0 small, 1 large).
struct ShapeConstants {
  double a0[2], K_a[2];   ///< area: reference area, stiffness
  double K_l[2], l0[2];   ///< segments: stiffness, rest length
  double bend_c[2];       ///< bending: c, 0 when off
  bool bending = false;
};

/// Four polygons' results, lane j = polygon j of the four, each array indexed [k * 4 + j].
class ShapeLanes {
 public:
  int n = 0;  ///< edges per polygon (the same for the four)
  double U_area[4] = {0, 0, 0, 0};
  double perimeter[4] = {0, 0, 0, 0};  ///< in any order of summation (a bound for the corner test)
  double longest = 0;                  ///< the longest edge of the four
  int grown = 0;                       ///< some edge outgrew its bound
  int may_fold = 0;                    ///< bit j: polygon j may fold somewhere (then vertex by vertex)
  const double* ex() const { return lane(kEx); }
  const double* ey() const { return lane(kEy); }
  const double* sq() const { return lane(kSq); }
  const double* seg_u() const { return lane(kSegU); }
  const double* bend_u() const { return lane(kBendU); }

  /// Polygons starting at first[0..3] (n vertices each, contiguous and cyclic), species sp[0..3]:
  /// their shape forces assigned to F (AoS x, y; zero before), the results above. bound: each
  /// edge's list bound (DpForceField::edge_bound), fold_w2: the fold test's squared width per
  /// species (fold_may_act; has_folds false: no fold test). energies false: U_area, seg_u and
  /// bend_u are left unset (a flow step needs none of them; the forces are the same).
  [[gnu::target("avx2")]] void run(const double* X, double* F, const int first[4], const int sp[4], int n_edges,
                                   const ShapeConstants& c, const double* bound, bool has_folds,
                                   const double fold_w2[2], bool energies);

 private:
  enum Array { kX, kY, kEx, kEy, kSq, kLen, kAx, kAy, kSx, kSy, kSegU, kInv, kUx, kUy, kBx, kBy, kBendU, kArrays };
  std::vector<double> storage_;
  int stride_ = 0;  ///< doubles per array: 4 (n + 2), one padding row each side
  const double* lane(Array a) const { return storage_.data() + a * stride_ + 4; }
  double* lane(Array a) { return storage_.data() + a * stride_ + 4; }
};

#if defined(__GNUC__)
namespace shape_lanes {
/// row k of a lane array (four doubles), as a pointer and loaded
[[gnu::always_inline]] inline double* at(double* a, int k) { return a + 4 * k; }
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d ld(const double* a, int k) { return _mm256_loadu_pd(a + 4 * k); }
/// a per-species constant in the four lanes
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d lanes_of(const double* per_species, const int sp[4]) {
  return _mm256_set_pd(per_species[sp[3]], per_species[sp[2]], per_species[sp[1]], per_species[sp[0]]);
}
}  // namespace shape_lanes

[[gnu::target("avx2")]] inline void ShapeLanes::run(const double* X, double* F, const int first[4], const int sp[4],
                                                    int n_edges, const ShapeConstants& c, const double* bound,
                                                    bool has_folds, const double fold_w2[2], bool energies) {
  using namespace shape_lanes;
  n = n_edges;
  if (4 * (n + 2) > stride_) {  // only when a polygon has more vertices than any before
    stride_ = 4 * (n + 2);
    storage_.assign(std::size_t(kArrays) * stride_, 0.0);
  }
  double* x = lane(kX);
  double* y = lane(kY);
  // positions: polygon j's vertex k into lane j (two 16-byte pairs per half, then unpack)
  for (int k = 0; k < n; ++k) {
    const __m128d a = _mm_loadu_pd(X + 2 * (first[0] + k)), b = _mm_loadu_pd(X + 2 * (first[1] + k));
    const __m128d cc = _mm_loadu_pd(X + 2 * (first[2] + k)), d = _mm_loadu_pd(X + 2 * (first[3] + k));
    const __m256d ac = _mm256_insertf128_pd(_mm256_castpd128_pd256(a), cc, 1);  // [xa ya | xc yc]
    const __m256d bd = _mm256_insertf128_pd(_mm256_castpd128_pd256(b), d, 1);   // [xb yb | xd yd]
    _mm256_storeu_pd(at(x, k), _mm256_unpacklo_pd(ac, bd));                    // [xa xb xc xd]
    _mm256_storeu_pd(at(y, k), _mm256_unpackhi_pd(ac, bd));
  }
  _mm256_storeu_pd(at(x, -1), ld(x, n - 1));
  _mm256_storeu_pd(at(y, -1), ld(y, n - 1));
  _mm256_storeu_pd(at(x, n), ld(x, 0));
  _mm256_storeu_pd(at(y, n), ld(y, 0));
  double *ex = lane(kEx), *ey = lane(kEy), *sq = lane(kSq), *len = lane(kLen);
  // PolygonEdges::measure; the area's sum in edge order (DpArea::vertex_forces); the bookkeeping
  const __m256d zero = _mm256_setzero_pd();
  __m256d twice_area = zero, perimeter = zero, longest = zero, grown = zero;
  for (int k = 0; k < n; ++k) {
    const __m256d dx = _mm256_sub_pd(ld(x, k + 1), ld(x, k)), dy = _mm256_sub_pd(ld(y, k + 1), ld(y, k));
    const __m256d q = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const __m256d l = _mm256_sqrt_pd(q);
    _mm256_storeu_pd(at(ex, k), dx);
    _mm256_storeu_pd(at(ey, k), dy);
    _mm256_storeu_pd(at(sq, k), q);
    _mm256_storeu_pd(at(len, k), l);
    twice_area = _mm256_add_pd(twice_area, _mm256_sub_pd(_mm256_mul_pd(ld(x, k), ld(y, k + 1)),
                                                         _mm256_mul_pd(ld(x, k + 1), ld(y, k))));
    perimeter = _mm256_add_pd(perimeter, l);
    longest = _mm256_max_pd(l, longest);  // l > longest ? l : longest (a maximum: the same value)
    const __m256d b = _mm256_set_pd(bound[first[3] + k], bound[first[2] + k], bound[first[1] + k], bound[first[0] + k]);
    grown = _mm256_or_pd(grown, _mm256_cmp_pd(q, _mm256_mul_pd(b, b), _CMP_GT_OQ));
  }
  _mm256_storeu_pd(at(ex, -1), ld(ex, n - 1));
  _mm256_storeu_pd(at(ey, -1), ld(ey, n - 1));
  _mm256_storeu_pd(at(sq, -1), ld(sq, n - 1));
  _mm256_storeu_pd(this->perimeter, perimeter);
  {
    double l4[4];
    _mm256_storeu_pd(l4, longest);
    this->longest = 0;
    for (double v : l4) this->longest = v > this->longest ? v : this->longest;
  }
  this->grown = _mm256_movemask_pd(grown) != 0;
  // area: force -dU/dr per vertex, energy per polygon
  const __m256d K_a = lanes_of(c.K_a, sp);
  const __m256d da = _mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(0.5), twice_area), lanes_of(c.a0, sp));
  const __m256d ca = _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-0.5), K_a), da);
  if (energies) _mm256_storeu_pd(U_area, _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(0.5), K_a), da), da));
  double *ax = lane(kAx), *ay = lane(kAy);
  for (int k = 0; k < n; ++k) {
    _mm256_storeu_pd(at(ax, k), _mm256_mul_pd(ca, _mm256_sub_pd(ld(y, k + 1), ld(y, k - 1))));
    _mm256_storeu_pd(at(ay, k), _mm256_mul_pd(ca, _mm256_sub_pd(ld(x, k - 1), ld(x, k + 1))));
  }
  // segments (DpSegmentLength::edge_forces)
  const __m256d K_l = lanes_of(c.K_l, sp), l0 = lanes_of(c.l0, sp);
  const __m256d half_K_l = _mm256_mul_pd(_mm256_set1_pd(0.5), K_l);
  const __m256d minus_K_l = _mm256_xor_pd(K_l, _mm256_set1_pd(-0.0));  // -k: the sign bit flipped, as unary minus
  double *sx = lane(kSx), *sy = lane(kSy), *su = lane(kSegU);
  for (int k = 0; k < n; ++k) {
    const __m256d stretch = _mm256_sub_pd(ld(len, k), l0);
    if (energies) _mm256_storeu_pd(at(su, k), _mm256_mul_pd(_mm256_mul_pd(half_K_l, stretch), stretch));
    const __m256d along = _mm256_div_pd(_mm256_mul_pd(minus_K_l, stretch), ld(len, k));
    _mm256_storeu_pd(at(sx, k), _mm256_mul_pd(along, ld(ex, k)));
    _mm256_storeu_pd(at(sy, k), _mm256_mul_pd(along, ld(ey, k)));
  }
  // bending (DpBending::edge_gradients)
  double *bx = lane(kBx), *by = lane(kBy), *bu = lane(kBendU);
  if (c.bending) {
    const __m256d cb = lanes_of(c.bend_c, sp);
    const __m256d two_c = _mm256_mul_pd(_mm256_set1_pd(2.0), cb);
    double *inv = lane(kInv), *ux = lane(kUx), *uy = lane(kUy);
    for (int k = 0; k < n; ++k) {
      const __m256d i = _mm256_div_pd(_mm256_set1_pd(1.0), ld(len, k));
      _mm256_storeu_pd(at(inv, k), i);
      _mm256_storeu_pd(at(ux, k), _mm256_mul_pd(ld(ex, k), i));
      _mm256_storeu_pd(at(uy, k), _mm256_mul_pd(ld(ey, k), i));
    }
    _mm256_storeu_pd(at(ux, -1), ld(ux, n - 1));
    _mm256_storeu_pd(at(uy, -1), ld(uy, n - 1));
    _mm256_storeu_pd(at(ux, n), ld(ux, 0));
    _mm256_storeu_pd(at(uy, n), ld(uy, 0));
    const __m256d two = _mm256_set1_pd(2.0);
    for (int k = 0; k < n; ++k) {
      const __m256d u = ld(ux, k), v = ld(uy, k), u1 = ld(ux, k + 1), v1 = ld(uy, k + 1);
      const __m256d tx = _mm256_sub_pd(u, u1), ty = _mm256_sub_pd(v, v1);
      if (energies) _mm256_storeu_pd(at(bu, k), _mm256_mul_pd(cb, _mm256_add_pd(_mm256_mul_pd(tx, tx), _mm256_mul_pd(ty, ty))));
      const __m256d gx = _mm256_mul_pd(two_c, _mm256_sub_pd(_mm256_sub_pd(_mm256_mul_pd(two, u), u1), ld(ux, k - 1)));
      const __m256d gy = _mm256_mul_pd(two_c, _mm256_sub_pd(_mm256_sub_pd(_mm256_mul_pd(two, v), v1), ld(uy, k - 1)));
      const __m256d g_along = _mm256_add_pd(_mm256_mul_pd(gx, u), _mm256_mul_pd(gy, v));
      _mm256_storeu_pd(at(bx, k), _mm256_mul_pd(_mm256_sub_pd(gx, _mm256_mul_pd(g_along, u)), ld(inv, k)));
      _mm256_storeu_pd(at(by, k), _mm256_mul_pd(_mm256_sub_pd(gy, _mm256_mul_pd(g_along, v)), ld(inv, k)));
    }
  }
  // each vertex's force in write_shape_forces' order: area, segments (edge k - 1 then k; for
  // vertex 0 edge 0 then n - 1), bending likewise; assigned (the vertices' forces are zero)
  for (int k = 0; k < n; ++k) {
    const int kp = k == 0 ? n - 1 : k - 1;
    __m256d fx, fy;
    if (k == 0) {
      fx = _mm256_add_pd(_mm256_sub_pd(_mm256_add_pd(zero, ld(ax, 0)), ld(sx, 0)), ld(sx, kp));
      fy = _mm256_add_pd(_mm256_sub_pd(_mm256_add_pd(zero, ld(ay, 0)), ld(sy, 0)), ld(sy, kp));
      if (c.bending) {
        fx = _mm256_sub_pd(_mm256_add_pd(fx, ld(bx, 0)), ld(bx, kp));
        fy = _mm256_sub_pd(_mm256_add_pd(fy, ld(by, 0)), ld(by, kp));
      }
    } else {
      fx = _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(zero, ld(ax, k)), ld(sx, kp)), ld(sx, k));
      fy = _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(zero, ld(ay, k)), ld(sy, kp)), ld(sy, k));
      if (c.bending) {
        fx = _mm256_add_pd(_mm256_sub_pd(fx, ld(bx, kp)), ld(bx, k));
        fy = _mm256_add_pd(_mm256_sub_pd(fy, ld(by, kp)), ld(by, k));
      }
    }
    const __m256d lo = _mm256_unpacklo_pd(fx, fy);  // [fx_a fy_a | fx_c fy_c]
    const __m256d hi = _mm256_unpackhi_pd(fx, fy);  // [fx_b fy_b | fx_d fy_d]
    _mm_storeu_pd(F + 2 * (first[0] + k), _mm256_castpd256_pd128(lo));
    _mm_storeu_pd(F + 2 * (first[1] + k), _mm256_castpd256_pd128(hi));
    _mm_storeu_pd(F + 2 * (first[2] + k), _mm256_extractf128_pd(lo, 1));
    _mm_storeu_pd(F + 2 * (first[3] + k), _mm256_extractf128_pd(hi, 1));
  }
  // the fold test of fold_may_act() per vertex (edges k - 1 and k), & for && (no branch)
  may_fold = 0;
  if (has_folds) {
    const __m256d w2 = lanes_of(fold_w2, sp);
    __m256d any = zero;
    for (int k = 0; k < n; ++k) {
      const __m256d dot = _mm256_add_pd(_mm256_mul_pd(ld(ex, k - 1), ld(ex, k)), _mm256_mul_pd(ld(ey, k - 1), ld(ey, k)));
      const __m256d all3 = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(dot, zero, _CMP_GT_OQ),
                                                       _mm256_cmp_pd(ld(sq, k - 1), w2, _CMP_GE_OQ)),
                                         _mm256_cmp_pd(ld(sq, k), w2, _CMP_GE_OQ));
      any = _mm256_or_pd(any, _mm256_andnot_pd(all3, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))));
    }
    may_fold = _mm256_movemask_pd(any);
  }
}
#endif

}  // namespace beverloo::avx2
