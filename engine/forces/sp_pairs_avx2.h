#pragma once
/// \file sp_pairs_avx2.h
/// \brief The 2D SP pair run four pairs at a time in AVX2, where the processor has it (chosen
/// at run time: the build stays free of host tuning), with exactly the bits of the SSE2 run
/// (sp_pairs_sse2.h) two pairs at a time.
///
/// Why: the SSE2 run spends most of its time in the square roots and divisions and in moving
/// pairs in and out of registers; a 256-bit sqrtpd and divpd do four pairs for about the price
/// of two. The four pairs' components are transposed into x and y registers (one lane per pair),
/// so each lane does exactly the SSE2 lane's IEEE operations in its order (no FMA: the functions
/// are compiled for "avx2" alone, and the build has -ffp-contract=off). Pairs a, b, c, d behave
/// as the SSE2 calls two_pairs(a, b) and two_pairs(c, d): the same forces added in the same
/// order, the same lane sums (a and c in lane 0, b and d in lane 1), and a half whose two pairs
/// both miss adds nothing, as the SSE2 call returns early. Hence the same bits, also of the
/// energy and power diagnostics (tests/physics/test_force_blocks.cpp compares all three widths).
/// Where all four add, the pairs of one row sum into F[i] in a register (see four_pairs_run).
/// The 3D step's pair run (four_pairs_run_3d) does the same for the scalar 3D loop's pairs.
#if defined(__x86_64__) && defined(__GNUC__)
#define BEVERLOO_HAVE_AVX2_PAIRS 1
#include <immintrin.h>

#include <cstddef>
#include <cstdint>

#include "sp_pairs_sse2.h"

namespace beverloo::avx2 {

/// Whether this processor runs the AVX2 pair run.
inline bool available() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return yes;
}

/// [lo hi] from two 128-bit halves.
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d join(__m128d lo, __m128d hi) {
  return _mm256_insertf128_pd(_mm256_castpd128_pd256(lo), hi, 1);
}
/// A per-pair-type table's values for pairs a, b, c, d (types ta .. td): two aligned loads of
/// its two-lane rows (PairTables: 4 ta + tb).
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d lanes4(const double (*table)[2], unsigned kab,
                                                                  unsigned kcd) {
  return join(_mm_load_pd(table[kab]), _mm_load_pd(table[kcd]));
}

/// Four pairs' contact test and repulsion, one lane per pair, from their squared distances r2
/// and their species-pair types (kab: 4 ta + tb, kcd: 4 tc + td): which touch (r2 < sigma^2).
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d touching4(__m256d r2, const sse2::PairTables& t,
                                                                     unsigned kab, unsigned kcd) {
  return _mm256_cmp_pd(r2, lanes4(t.lanes_sig2, kab, kcd), _CMP_LT_OQ);
}
/// ... and for pairs that may touch: r = sqrt(r2), the overlap ov = 1 - r/sigma (0 where not
/// touching) and the returned scale (eps ov / sigma) / r of the force along x_i - x_j, in the
/// scalar pair's order (SpContact::pair_force).
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d repulsion4(__m256d r2, __m256d touching,
                                                                      const sse2::PairTables& t, unsigned kab,
                                                                      unsigned kcd, __m256d& r, __m256d& ov) {
  r = _mm256_sqrt_pd(r2);
  const __m256d inv_sig = lanes4(t.lanes_inv_sig, kab, kcd);
  ov = _mm256_and_pd(touching, _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_mul_pd(r, inv_sig)));
  return _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(lanes4(t.lanes_eps, kab, kcd), ov), inv_sig), r);
}

/// Pairs q .. of a block's run, four at a time, while four are left; returns where it stopped
/// (the caller goes on two at a time). Items below hi are the run's block's (see two_pairs).
template <sse2::Friction kFriction, bool kSums>
[[gnu::target("avx2")]] int four_pairs_run(const double* X, const double* V, double* F, const int* I, const int* J,
                                           const std::uint8_t* T, int q, int q_end, std::size_t hi,
                                           const sse2::PairTables& t, double mu_n, double mu_t,
                                           sse2::LaneSums& sums) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d minus_mu_n = _mm256_set1_pd(-mu_n), mu_t4 = _mm256_set1_pd(mu_t), minus_mu_t = _mm256_set1_pd(-mu_t);
  const auto u = [](int k) { return static_cast<std::size_t>(static_cast<unsigned>(k)); };  // k >= 0
  // the lane sums in registers (through the reference, in memory on every pair)
  __m128d max_ov = sums.max_ov, energy_sum = sums.energy, power_sum = sums.power;
  for (; q_end - q >= 4; q += 4) {
    const std::size_t ia = u(I[q]), ja = u(J[q]), ib = u(I[q + 1]), jb = u(J[q + 1]);
    const std::size_t ic = u(I[q + 2]), jc = u(J[q + 2]), id = u(I[q + 3]), jd = u(J[q + 3]);
    // x_i - x_j per pair, as [dx dy] of a and c, and of b and d; then transposed: one lane per pair
    const __m256d d_ac = _mm256_sub_pd(join(_mm_loadu_pd(X + 2 * ia), _mm_loadu_pd(X + 2 * ic)),
                                       join(_mm_loadu_pd(X + 2 * ja), _mm_loadu_pd(X + 2 * jc)));
    const __m256d d_bd = _mm256_sub_pd(join(_mm_loadu_pd(X + 2 * ib), _mm_loadu_pd(X + 2 * id)),
                                       join(_mm_loadu_pd(X + 2 * jb), _mm_loadu_pd(X + 2 * jd)));
    const __m256d dx = _mm256_unpacklo_pd(d_ac, d_bd);  // [dx_a dx_b dx_c dx_d]
    const __m256d dy = _mm256_unpackhi_pd(d_ac, d_bd);
    const __m256d r2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const unsigned kab = 4u * T[q] + T[q + 1], kcd = 4u * T[q + 2] + T[q + 3];
    const __m256d touching = touching4(r2, t, kab, kcd);
    const int m = _mm256_movemask_pd(touching);
    if (m == 0) continue;
    __m256d r, ov;
    const __m256d scale = repulsion4(r2, touching, t, kab, kcd, r, ov);
    __m256d fx = _mm256_mul_pd(scale, dx), fy = _mm256_mul_pd(scale, dy);
    __m256d power = _mm256_setzero_pd();
    if constexpr (kFriction != sse2::Friction::None) {
      const __m256d v_ac = _mm256_sub_pd(join(_mm_loadu_pd(V + 2 * ia), _mm_loadu_pd(V + 2 * ic)),
                                         join(_mm_loadu_pd(V + 2 * ja), _mm_loadu_pd(V + 2 * jc)));
      const __m256d v_bd = _mm256_sub_pd(join(_mm_loadu_pd(V + 2 * ib), _mm_loadu_pd(V + 2 * id)),
                                         join(_mm_loadu_pd(V + 2 * jb), _mm_loadu_pd(V + 2 * jd)));
      const __m256d dvx = _mm256_unpacklo_pd(v_ac, v_bd), dvy = _mm256_unpackhi_pd(v_ac, v_bd);
      __m256d ffx, ffy;
      if constexpr (kFriction == sse2::Friction::Split) {
        const __m256d inv_r = _mm256_div_pd(one, r);
        const __m256d nx = _mm256_mul_pd(dx, inv_r), ny = _mm256_mul_pd(dy, inv_r);
        const __m256d dot = _mm256_add_pd(_mm256_mul_pd(dvx, nx), _mm256_mul_pd(dvy, ny));
        const __m256d dvnx = _mm256_mul_pd(dot, nx), dvny = _mm256_mul_pd(dot, ny);
        ffx = _mm256_sub_pd(_mm256_mul_pd(minus_mu_n, dvnx), _mm256_mul_pd(mu_t4, _mm256_sub_pd(dvx, dvnx)));
        ffy = _mm256_sub_pd(_mm256_mul_pd(minus_mu_n, dvny), _mm256_mul_pd(mu_t4, _mm256_sub_pd(dvy, dvny)));
      } else {
        ffx = _mm256_mul_pd(minus_mu_t, dvx);
        ffy = _mm256_mul_pd(minus_mu_t, dvy);
      }
      ffx = _mm256_and_pd(touching, ffx);
      ffy = _mm256_and_pd(touching, ffy);
      if constexpr (kSums) power = _mm256_add_pd(_mm256_mul_pd(ffx, dvx), _mm256_mul_pd(ffy, dvy));
      fx = _mm256_add_pd(fx, ffx);
      fy = _mm256_add_pd(fy, ffy);
    }
    __m256d energy = _mm256_setzero_pd();
    if constexpr (kSums) energy = _mm256_mul_pd(_mm256_mul_pd(lanes4(t.lanes_half_eps, kab, kcd), ov), ov);
    // back to one register per pair: [fx fy] of a and c, of b and d
    const __m256d f_ac = _mm256_unpacklo_pd(fx, fy), f_bd = _mm256_unpackhi_pd(fx, fy);
    const __m128d fa = _mm256_castpd256_pd128(f_ac), fb = _mm256_castpd256_pd128(f_bd);
    const __m128d fc = _mm256_extractf128_pd(f_ac, 1), fd = _mm256_extractf128_pd(f_bd, 1);
    // pairs a and b (the first SSE2 call), then c and d (the second), each only if one of its
    // two touches; the sums lane by lane in that order
    const bool on_ab = (m & 3) != 0, on_cd = (m & 12) != 0;
    if (on_ab) {
      if constexpr (kSums) {
        energy_sum = _mm_add_pd(energy_sum, _mm256_castpd256_pd128(energy));
        power_sum = _mm_add_pd(power_sum, _mm256_castpd256_pd128(power));
      }
      max_ov = _mm_max_pd(max_ov, _mm256_castpd256_pd128(ov));
    }
    if (on_cd) {
      if constexpr (kSums) {
        energy_sum = _mm_add_pd(energy_sum, _mm256_extractf128_pd(energy, 1));
        power_sum = _mm_add_pd(power_sum, _mm256_extractf128_pd(power, 1));
      }
      max_ov = _mm_max_pd(max_ov, _mm256_extractf128_pd(ov, 1));
    }
    if (on_ab && on_cd) {
      // All four add to their items (the common case). The pairs of one row (equal i, adjacent
      // in the run) add to F[i] in a register, in their order, instead of through a store and
      // reload per pair (that chain set the pace). The j's first: a j is never the i of its own
      // or an earlier pair (j > i, and i does not decrease along the run), so every F[i] then
      // holds what it held when the sequential code reached it, and the sums are its bits.
      if (ja < hi) _mm_storeu_pd(F + 2 * ja, _mm_sub_pd(_mm_loadu_pd(F + 2 * ja), fa));
      if (jb < hi) _mm_storeu_pd(F + 2 * jb, _mm_sub_pd(_mm_loadu_pd(F + 2 * jb), fb));
      if (jc < hi) _mm_storeu_pd(F + 2 * jc, _mm_sub_pd(_mm_loadu_pd(F + 2 * jc), fc));
      if (jd < hi) _mm_storeu_pd(F + 2 * jd, _mm_sub_pd(_mm_loadu_pd(F + 2 * jd), fd));
      // whether each pair's i is the previous pair's: [-, b, c, d] from [ia ib ic id] against [ia ia ib ic]
      const __m128i is = _mm_loadu_si128(reinterpret_cast<const __m128i*>(I + q));
      const __m128i same = _mm_cmpeq_epi32(is, _mm_shuffle_epi32(is, 0x90));
      const __m128d sa = _mm_add_pd(_mm_loadu_pd(F + 2 * ia), fa);
      const __m128d sb =
          _mm_add_pd(_mm_blendv_pd(_mm_loadu_pd(F + 2 * ib), sa, _mm_castsi128_pd(_mm_shuffle_epi32(same, 0x55))), fb);
      const __m128d sc =
          _mm_add_pd(_mm_blendv_pd(_mm_loadu_pd(F + 2 * ic), sb, _mm_castsi128_pd(_mm_shuffle_epi32(same, 0xaa))), fc);
      const __m128d sd =
          _mm_add_pd(_mm_blendv_pd(_mm_loadu_pd(F + 2 * id), sc, _mm_castsi128_pd(_mm_shuffle_epi32(same, 0xff))), fd);
      // in order: where i repeats, the later store holds the later sum
      _mm_storeu_pd(F + 2 * ia, sa);
      _mm_storeu_pd(F + 2 * ib, sb);
      _mm_storeu_pd(F + 2 * ic, sc);
      _mm_storeu_pd(F + 2 * id, sd);
      continue;
    }
    if (on_ab) {
      _mm_storeu_pd(F + 2 * ia, _mm_add_pd(_mm_loadu_pd(F + 2 * ia), fa));
      if (ja < hi) _mm_storeu_pd(F + 2 * ja, _mm_sub_pd(_mm_loadu_pd(F + 2 * ja), fa));
      _mm_storeu_pd(F + 2 * ib, _mm_add_pd(_mm_loadu_pd(F + 2 * ib), fb));
      if (jb < hi) _mm_storeu_pd(F + 2 * jb, _mm_sub_pd(_mm_loadu_pd(F + 2 * jb), fb));
    }
    if (on_cd) {
      _mm_storeu_pd(F + 2 * ic, _mm_add_pd(_mm_loadu_pd(F + 2 * ic), fc));
      if (jc < hi) _mm_storeu_pd(F + 2 * jc, _mm_sub_pd(_mm_loadu_pd(F + 2 * jc), fc));
      _mm_storeu_pd(F + 2 * id, _mm_add_pd(_mm_loadu_pd(F + 2 * id), fd));
      if (jd < hi) _mm_storeu_pd(F + 2 * jd, _mm_sub_pd(_mm_loadu_pd(F + 2 * jd), fd));
    }
  }
  sums.max_ov = max_ov;
  if constexpr (kSums) {
    sums.energy = energy_sum;
    sums.power = power_sum;
  }
  return q;
}

/// 3D: a particle's [x y z] as [x y z 0] (a masked load: no read past the array's end).
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d load3(const double* p) {
  return _mm256_maskload_pd(p, _mm256_set_epi64x(0, -1, -1, -1));
}
/// 3D: stores the first three lanes of v at p.
[[gnu::always_inline, gnu::target("avx2")]] inline void store3(double* p, __m256d v) {
  _mm_storeu_pd(p, _mm256_castpd256_pd128(v));
  _mm_store_sd(p + 2, _mm256_extractf128_pd(v, 1));
}
/// 3D: [x y z *] of pairs a, b, c, d into one register per component, [x_a x_b x_c x_d] ...
[[gnu::always_inline, gnu::target("avx2")]] inline void transpose_in(__m256d a, __m256d b, __m256d c, __m256d d,
                                                                    __m256d& x, __m256d& y, __m256d& z) {
  const __m256d t0 = _mm256_unpacklo_pd(a, b), t1 = _mm256_unpackhi_pd(a, b);  // [xa xb za zb], [ya yb - -]
  const __m256d t2 = _mm256_unpacklo_pd(c, d), t3 = _mm256_unpackhi_pd(c, d);
  x = _mm256_permute2f128_pd(t0, t2, 0x20);
  z = _mm256_permute2f128_pd(t0, t2, 0x31);
  y = _mm256_permute2f128_pd(t1, t3, 0x20);
}

/// Four 32-bit lanes of a mask (all equal) as four 64-bit lanes.
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d widen(__m128i mask32) {
  return _mm256_castsi256_pd(_mm256_cvtepi32_epi64(mask32));
}

/// 3D: the scalar pair loop's pairs q .. of a block's run four at a time in AVX2, while four are
/// left, for a step (SpContact::block_and_kick: the forces and the largest overlap, no energy or
/// power); returns where it stopped (the caller goes on one at a time). Each lane does the
/// scalar pair's operations in its order (SpContact::pair_force, touching_pair), and a pair that
/// does not touch adds nothing, as in the scalar loop, so the forces are its bits. The pairs of
/// one row add to F[i] in a register in their order (the j updates first: a j is never the i of
/// its own or an earlier pair). max_ov: the largest overlap seen (of touching pairs).
template <sse2::Friction kFriction>
[[gnu::target("avx2")]] int four_pairs_run_3d(const double* X, const double* V, double* F, const int* I, const int* J,
                                              const std::uint8_t* T, int q, int q_end, std::size_t hi,
                                              const sse2::PairTables& t, double mu_n, double mu_t, double& max_ov) {
  const __m256d one = _mm256_set1_pd(1.0), zero = _mm256_setzero_pd();
  const __m256d minus_mu_n = _mm256_set1_pd(-mu_n), mu_t4 = _mm256_set1_pd(mu_t), minus_mu_t = _mm256_set1_pd(-mu_t);
  const auto u = [](int k) { return static_cast<std::size_t>(static_cast<unsigned>(k)); };  // k >= 0
  __m256d largest = _mm256_set1_pd(max_ov);
  for (; q_end - q >= 4; q += 4) {
    const std::size_t ia = u(I[q]), ja = u(J[q]), ib = u(I[q + 1]), jb = u(J[q + 1]);
    const std::size_t ic = u(I[q + 2]), jc = u(J[q + 2]), id = u(I[q + 3]), jd = u(J[q + 3]);
    __m256d dx, dy, dz;
    transpose_in(_mm256_sub_pd(load3(X + 3 * ia), load3(X + 3 * ja)), _mm256_sub_pd(load3(X + 3 * ib), load3(X + 3 * jb)),
                 _mm256_sub_pd(load3(X + 3 * ic), load3(X + 3 * jc)), _mm256_sub_pd(load3(X + 3 * id), load3(X + 3 * jd)),
                 dx, dy, dz);
    // r2 = dx^2 + dy^2 + dz^2, left to right as the scalar sum (0 + dx^2 is dx^2)
    const __m256d r2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
    const unsigned kab = 4u * T[q] + T[q + 1], kcd = 4u * T[q + 2] + T[q + 3];
    const __m256d touching = touching4(r2, t, kab, kcd);
    const int m = _mm256_movemask_pd(touching);
    if (m == 0) continue;
    __m256d r, ov;
    const __m256d scale = repulsion4(r2, touching, t, kab, kcd, r, ov);
    largest = _mm256_max_pd(ov, largest);  // a NaN overlap leaves the largest as it was, as the scalar test
    __m256d fx = _mm256_mul_pd(scale, dx), fy = _mm256_mul_pd(scale, dy), fz = _mm256_mul_pd(scale, dz);
    if constexpr (kFriction != sse2::Friction::None) {
      __m256d dvx, dvy, dvz;
      transpose_in(_mm256_sub_pd(load3(V + 3 * ia), load3(V + 3 * ja)), _mm256_sub_pd(load3(V + 3 * ib), load3(V + 3 * jb)),
                   _mm256_sub_pd(load3(V + 3 * ic), load3(V + 3 * jc)), _mm256_sub_pd(load3(V + 3 * id), load3(V + 3 * jd)),
                   dvx, dvy, dvz);
      if constexpr (kFriction == sse2::Friction::Split) {
        const __m256d inv_r = _mm256_div_pd(one, r);
        const __m256d nx = _mm256_mul_pd(dx, inv_r), ny = _mm256_mul_pd(dy, inv_r), nz = _mm256_mul_pd(dz, inv_r);
        // dv . n from 0, left to right, as the scalar sum
        const __m256d dot = _mm256_add_pd(
            _mm256_add_pd(_mm256_add_pd(zero, _mm256_mul_pd(dvx, nx)), _mm256_mul_pd(dvy, ny)), _mm256_mul_pd(dvz, nz));
        const __m256d dvnx = _mm256_mul_pd(dot, nx), dvny = _mm256_mul_pd(dot, ny), dvnz = _mm256_mul_pd(dot, nz);
        fx = _mm256_add_pd(fx, _mm256_sub_pd(_mm256_mul_pd(minus_mu_n, dvnx), _mm256_mul_pd(mu_t4, _mm256_sub_pd(dvx, dvnx))));
        fy = _mm256_add_pd(fy, _mm256_sub_pd(_mm256_mul_pd(minus_mu_n, dvny), _mm256_mul_pd(mu_t4, _mm256_sub_pd(dvy, dvny))));
        fz = _mm256_add_pd(fz, _mm256_sub_pd(_mm256_mul_pd(minus_mu_n, dvnz), _mm256_mul_pd(mu_t4, _mm256_sub_pd(dvz, dvnz))));
      } else {
        fx = _mm256_add_pd(fx, _mm256_mul_pd(minus_mu_t, dvx));
        fy = _mm256_add_pd(fy, _mm256_mul_pd(minus_mu_t, dvy));
        fz = _mm256_add_pd(fz, _mm256_mul_pd(minus_mu_t, dvz));
      }
    }
    // back to one register per pair, [fx fy fz fz]
    const __m256d u0 = _mm256_unpacklo_pd(fx, fy), u1 = _mm256_unpackhi_pd(fx, fy);
    const __m256d u2 = _mm256_unpacklo_pd(fz, fz), u3 = _mm256_unpackhi_pd(fz, fz);
    const __m256d fa = _mm256_permute2f128_pd(u0, u2, 0x20), fc = _mm256_permute2f128_pd(u0, u2, 0x31);
    const __m256d fb = _mm256_permute2f128_pd(u1, u3, 0x20), fd = _mm256_permute2f128_pd(u1, u3, 0x31);
    // the j's of the touching pairs, in order
    if ((m & 1) && ja < hi) store3(F + 3 * ja, _mm256_sub_pd(load3(F + 3 * ja), fa));
    if ((m & 2) && jb < hi) store3(F + 3 * jb, _mm256_sub_pd(load3(F + 3 * jb), fb));
    if ((m & 4) && jc < hi) store3(F + 3 * jc, _mm256_sub_pd(load3(F + 3 * jc), fc));
    if ((m & 8) && jd < hi) store3(F + 3 * jd, _mm256_sub_pd(load3(F + 3 * jd), fd));
    // the i's: a pair's start is the previous pair's sum where its i is the previous pair's,
    // else F[i]; a touching pair adds its force (a pair that misses keeps the start)
    const __m128i is = _mm_loadu_si128(reinterpret_cast<const __m128i*>(I + q));
    const __m128i same = _mm_cmpeq_epi32(is, _mm_shuffle_epi32(is, 0x90));
    const __m256d ta = _mm256_permute4x64_pd(touching, 0x00), tb = _mm256_permute4x64_pd(touching, 0x55);
    const __m256d tc = _mm256_permute4x64_pd(touching, 0xaa), td = _mm256_permute4x64_pd(touching, 0xff);
    const __m256d start_a = load3(F + 3 * ia);
    const __m256d sa = _mm256_blendv_pd(start_a, _mm256_add_pd(start_a, fa), ta);
    const __m256d start_b = _mm256_blendv_pd(load3(F + 3 * ib), sa, widen(_mm_shuffle_epi32(same, 0x55)));
    const __m256d sb = _mm256_blendv_pd(start_b, _mm256_add_pd(start_b, fb), tb);
    const __m256d start_c = _mm256_blendv_pd(load3(F + 3 * ic), sb, widen(_mm_shuffle_epi32(same, 0xaa)));
    const __m256d sc = _mm256_blendv_pd(start_c, _mm256_add_pd(start_c, fc), tc);
    const __m256d start_d = _mm256_blendv_pd(load3(F + 3 * id), sc, widen(_mm_shuffle_epi32(same, 0xff)));
    const __m256d sd = _mm256_blendv_pd(start_d, _mm256_add_pd(start_d, fd), td);
    // in order: where i repeats, the later store holds the later sum
    store3(F + 3 * ia, sa);
    store3(F + 3 * ib, sb);
    store3(F + 3 * ic, sc);
    store3(F + 3 * id, sd);
  }
  const __m128d halves = _mm_max_pd(_mm256_extractf128_pd(largest, 1), _mm256_castpd256_pd128(largest));
  const double lo = _mm_cvtsd_f64(halves), hi_lane = _mm_cvtsd_f64(_mm_unpackhi_pd(halves, halves));
  max_ov = lo > hi_lane ? lo : hi_lane;
  return q;
}

}  // namespace beverloo::avx2
#else
namespace beverloo::avx2 {
inline bool available() { return false; }  // not an x86-64 GCC build: the SSE2 or scalar paths
}  // namespace beverloo::avx2
#endif
