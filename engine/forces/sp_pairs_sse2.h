#pragma once
/// \file sp_pairs_sse2.h
/// \brief The 2D SP pair loop (a block's pair run), two pairs at a time in SSE2 (every x86-64
/// has it, so no host tuning and the same bits on every node).
///
/// Why: a pair's cost is its square root and division; sqrtpd and divpd do two pairs for about
/// the price of one. Each lane does exactly the scalar pair's
/// operations in the scalar order (SpContact::pair_force), so the forces are the same bits as
/// the scalar loop's (tests/physics/test_force_blocks.cpp compares them); a pair that does not
/// touch gets overlap 0 and adds +-0. Only the energy and friction-power sums (diagnostics) add
/// in another order.
#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstddef>
#include <cstdint>

namespace beverloo::sse2 {

/// Per species-pair type t = 2 si + sj (NeighborList::pair_type): contact distance^2, its
/// inverse, eps/2, eps; and the same per pair of types (4 ta + tb: lane 0 type ta, lane 1 type
/// tb), so that two pairs' values come in one aligned load instead of two loads and a shuffle.
struct PairTables {
  double sig2[4], inv_sig[4], half_eps[4], eps[4];
  alignas(16) double lanes_sig2[16][2], lanes_inv_sig[16][2], lanes_half_eps[16][2], lanes_eps[16][2];
  void make_lanes() {
    for (int ta = 0; ta < 4; ++ta)
      for (int tb = 0; tb < 4; ++tb) {
        const int k = 4 * ta + tb;
        lanes_sig2[k][0] = sig2[ta], lanes_sig2[k][1] = sig2[tb];
        lanes_inv_sig[k][0] = inv_sig[ta], lanes_inv_sig[k][1] = inv_sig[tb];
        lanes_half_eps[k][0] = half_eps[ta], lanes_half_eps[k][1] = half_eps[tb];
        lanes_eps[k][0] = eps[ta], lanes_eps[k][1] = eps[tb];
      }
  }
};

/// Running sums of a block: two lanes each, added up at the end.
struct LaneSums {
  __m128d energy = _mm_setzero_pd(), power = _mm_setzero_pd(), max_ov = _mm_setzero_pd();
};

enum class Friction { None, Full, Split };

/// The friction coefficients as the lanes use them, made once per run (in the loop, the
/// compiler reloaded and negated them on every pair: the force stores might alias them).
struct FrictionLanes {
  __m128d minus_mu_n, mu_t, minus_mu_t;
  FrictionLanes(double mu_n, double mu_t_)
      : minus_mu_n(_mm_set1_pd(-mu_n)), mu_t(_mm_set1_pd(mu_t_)), minus_mu_t(_mm_set1_pd(-mu_t_)) {}
};

/// Pairs (ia, ja) and (ib, jb) of a block's pair run, of species-pair types ta and tb
/// (NeighborList::pair_type): each pair's force added to its i and
/// subtracted from its j if j < hi (j's block is this one; else j's block adds it from its
/// incoming list), pair a first, as the scalar loop does. kSums: also the energy and the
/// friction power (diagnostics; a step needs only the forces and the largest overlap).
/// Indices as std::size_t: from an int, each address took a sign extension and two leas.
template <Friction kFriction, bool kSums>
[[gnu::always_inline]] inline void two_pairs(const double* X, const double* V, double* F, std::size_t ia,
                                             std::size_t ja, std::size_t ib, std::size_t jb, unsigned ta, unsigned tb,
                                             std::size_t hi, const PairTables& t, const FrictionLanes& mu,
                                             LaneSums& sums) {
  const __m128d xia = _mm_loadu_pd(X + 2 * ia), xib = _mm_loadu_pd(X + 2 * ib);
  const __m128d dxa = _mm_sub_pd(xia, _mm_loadu_pd(X + 2 * ja));
  const __m128d dxb = _mm_sub_pd(xib, _mm_loadu_pd(X + 2 * jb));
  const __m128d sqa = _mm_mul_pd(dxa, dxa), sqb = _mm_mul_pd(dxb, dxb);
  // r2 = dx0^2 + dx1^2 for each pair: lane 0 pair a, lane 1 pair b
  const __m128d r2 = _mm_add_pd(_mm_unpacklo_pd(sqa, sqb), _mm_unpackhi_pd(sqa, sqb));
  const unsigned k = 4 * ta + tb;
  const __m128d touching = _mm_cmplt_pd(r2, _mm_load_pd(t.lanes_sig2[k]));
  if (_mm_movemask_pd(touching) == 0) return;
  const __m128d r = _mm_sqrt_pd(r2);
  const __m128d one = _mm_set1_pd(1.0);
  const __m128d inv_sig = _mm_load_pd(t.lanes_inv_sig[k]);
  const __m128d ov = _mm_and_pd(touching, _mm_sub_pd(one, _mm_mul_pd(r, inv_sig)));
  // 0.5 * eps * ov * ov, as the scalar (0.5 * eps) * ov * ov
  if constexpr (kSums)
    sums.energy = _mm_add_pd(sums.energy, _mm_mul_pd(_mm_mul_pd(_mm_load_pd(t.lanes_half_eps[k]), ov), ov));
  sums.max_ov = _mm_max_pd(sums.max_ov, ov);
  const __m128d scale = _mm_div_pd(
      _mm_mul_pd(_mm_mul_pd(_mm_load_pd(t.lanes_eps[k]), ov), inv_sig), r);
  __m128d fa = _mm_mul_pd(_mm_unpacklo_pd(scale, scale), dxa);
  __m128d fb = _mm_mul_pd(_mm_unpackhi_pd(scale, scale), dxb);
  if constexpr (kFriction != Friction::None) {
    const __m128d on_a = _mm_unpacklo_pd(touching, touching), on_b = _mm_unpackhi_pd(touching, touching);
    const __m128d dva = _mm_sub_pd(_mm_loadu_pd(V + 2 * ia), _mm_loadu_pd(V + 2 * ja));
    const __m128d dvb = _mm_sub_pd(_mm_loadu_pd(V + 2 * ib), _mm_loadu_pd(V + 2 * jb));
    __m128d ffa, ffb;
    if constexpr (kFriction == Friction::Split) {
      const __m128d inv_r = _mm_div_pd(one, r);
      const __m128d na = _mm_mul_pd(dxa, _mm_unpacklo_pd(inv_r, inv_r));
      const __m128d nb = _mm_mul_pd(dxb, _mm_unpackhi_pd(inv_r, inv_r));
      const __m128d pa = _mm_mul_pd(dva, na), pb = _mm_mul_pd(dvb, nb);
      // dv . n = dv0 n0 + dv1 n1 per pair
      const __m128d dot = _mm_add_pd(_mm_unpacklo_pd(pa, pb), _mm_unpackhi_pd(pa, pb));
      const __m128d dvna = _mm_mul_pd(_mm_unpacklo_pd(dot, dot), na);
      const __m128d dvnb = _mm_mul_pd(_mm_unpackhi_pd(dot, dot), nb);
      ffa = _mm_sub_pd(_mm_mul_pd(mu.minus_mu_n, dvna), _mm_mul_pd(mu.mu_t, _mm_sub_pd(dva, dvna)));
      ffb = _mm_sub_pd(_mm_mul_pd(mu.minus_mu_n, dvnb), _mm_mul_pd(mu.mu_t, _mm_sub_pd(dvb, dvnb)));
    } else {
      ffa = _mm_mul_pd(mu.minus_mu_t, dva);
      ffb = _mm_mul_pd(mu.minus_mu_t, dvb);
    }
    ffa = _mm_and_pd(on_a, ffa);
    ffb = _mm_and_pd(on_b, ffb);
    if constexpr (kSums) {
      const __m128d wa = _mm_mul_pd(ffa, dva), wb = _mm_mul_pd(ffb, dvb);
      sums.power = _mm_add_pd(sums.power, _mm_add_pd(_mm_unpacklo_pd(wa, wb), _mm_unpackhi_pd(wa, wb)));
    }
    fa = _mm_add_pd(fa, ffa);
    fb = _mm_add_pd(fb, ffb);
  }
  // in the scalar order: i then j of pair a, then of pair b (ib may be ia or ja)
  _mm_storeu_pd(F + 2 * ia, _mm_add_pd(_mm_loadu_pd(F + 2 * ia), fa));
  if (ja < hi) _mm_storeu_pd(F + 2 * ja, _mm_sub_pd(_mm_loadu_pd(F + 2 * ja), fa));
  _mm_storeu_pd(F + 2 * ib, _mm_add_pd(_mm_loadu_pd(F + 2 * ib), fb));
  if (jb < hi) _mm_storeu_pd(F + 2 * jb, _mm_sub_pd(_mm_loadu_pd(F + 2 * jb), fb));
}

inline double sum_lanes(__m128d v) { return _mm_cvtsd_f64(v) + _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
inline double max_lanes(__m128d v) {
  const double a = _mm_cvtsd_f64(v), b = _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
  return a > b ? a : b;
}

}  // namespace beverloo::sse2
#endif
