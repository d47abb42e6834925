#pragma once
/// \file sp_sweeps_avx2.h
/// \brief The 2D SP step's two sweeps (the drift with its tests and force start, the kick) two
/// particles at a time in AVX2, where the processor has it (chosen at run time), with exactly
/// the bits of sp_sweeps.h's one particle at a time.
///
/// Why: in 2D a particle's x and y fill half a 256-bit register, so one instruction does two
/// particles' drift or kick; the sweeps are a third of a step in the drag-only bench case. Each
/// lane does the SSE2 lane's IEEE operations in its order (compiled for "avx2" alone: no FMA;
/// the build has -ffp-contract=off), and the tests (the displacement, the exit watch, the
/// finiteness) give the same answers, so the step's results are the same bits
/// (tests/physics/test_fused_step.cpp compares the step with the plain drift() of
/// velocity_verlet.h and evaluate(), bit for bit).
#include "sp_sweeps.h"

#if defined(__x86_64__) && defined(__GNUC__)
#define BEVERLOO_HAVE_AVX2_SWEEPS 1
#include <immintrin.h>

#include "../forces/sp_pairs_avx2.h"  // avx2::available()

namespace beverloo::avx2 {

/// Two particles' per-species constants side by side, indexed by 2 species(i) + species(i + 1):
/// the force start's -c (drag) on both components and the weight on the upward one.
struct DriftLanes {
  alignas(32) double minus_drag[4][4];
  alignas(32) double weight[4][4];
  explicit DriftLanes(const DriftConstants& k) {
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const int t = 2 * a + b;
        minus_drag[t][0] = minus_drag[t][1] = -k.drag[a];
        minus_drag[t][2] = minus_drag[t][3] = -k.drag[b];
        weight[t][0] = 0.0, weight[t][1] = k.weight[a];
        weight[t][2] = 0.0, weight[t][3] = k.weight[b];
      }
  }
};

/// [m_i m_i m_i+1 m_i+1] from m + i.
[[gnu::always_inline, gnu::target("avx2")]] inline __m256d per_particle(const double* m, int i) {
  return _mm256_permute4x64_pd(_mm256_castpd128_pd256(_mm_loadu_pd(m + i)), 0x50);
}

/// drift_range<2>() (sp_sweeps.h) two particles at a time; the odd last one as there.
[[gnu::target("avx2")]] inline bool drift_range_2d(int lo, int hi, double* __restrict X, double* __restrict V,
                                                   double* __restrict F, const double* __restrict inv_m,
                                                   const std::uint8_t* __restrict species,
                                                   const std::uint8_t* __restrict exited, const DriftConstants k,
                                                   int& exiting) {
  const DriftLanes lanes(k);
  const __m256d dt = _mm256_set1_pd(k.dt), half_dt = _mm256_set1_pd(k.half_dt), half_dt2 = _mm256_set1_pd(k.half_dt2);
  const __m256d limit2 = _mm256_set1_pd(k.limit2), zero = _mm256_setzero_pd();
  // per species, the exited particles' depth for the exit watch, in the upward lanes
  const double below[2] = {k.watch.exited_below[0], k.watch.exited_below[1]};
  const bool measure = k.reference != nullptr;
  int moved = 0, exits = 0;
  int i = lo;
  for (; hi - i >= 2; i += 2) {
    const int t = 2 * species[i] + species[i + 1];
    const __m256d a = _mm256_mul_pd(_mm256_loadu_pd(F + 2 * i), per_particle(inv_m, i));
    const __m256d v = _mm256_loadu_pd(V + 2 * i);
    const __m256d x = _mm256_add_pd(_mm256_loadu_pd(X + 2 * i),
                                    _mm256_add_pd(_mm256_mul_pd(dt, v), _mm256_mul_pd(half_dt2, a)));
    const __m256d v_new = _mm256_add_pd(v, _mm256_mul_pd(half_dt, a));
    _mm256_storeu_pd(X + 2 * i, x);
    _mm256_storeu_pd(V + 2 * i, v_new);
    if (measure) {
      const __m256d u = _mm256_sub_pd(x, _mm256_loadu_pd(k.reference + 2 * i));
      const __m256d uu = _mm256_mul_pd(u, u);
      const __m256d d2 = _mm256_hadd_pd(uu, uu);  // [u0^2 + u1^2 (twice), the same of i + 1]
      moved |= _mm256_movemask_pd(_mm256_cmp_pd(d2, limit2, _CMP_GT_OQ));
    }
    // ExitCounter's tests on the heights (lanes 1 and 3): h < below[species] if counted, else !(h >= 0)
    const __m256d below4 = _mm256_set_pd(below[species[i + 1]], 0.0, below[species[i]], 0.0);
    const int deep = _mm256_movemask_pd(_mm256_cmp_pd(x, below4, _CMP_LT_OQ));
    const int not_up = _mm256_movemask_pd(_mm256_cmp_pd(x, zero, _CMP_NGE_UQ));
    exits |= (exited[i] ? deep >> 1 : not_up >> 1) & 1;
    exits |= (exited[i + 1] ? deep >> 3 : not_up >> 3) & 1;
    // (-c v0, -c v1 - m g) per particle: the lanes without gravity subtract +0
    const __m256d f = _mm256_sub_pd(_mm256_mul_pd(_mm256_load_pd(lanes.minus_drag[t]), v_new),
                                    _mm256_load_pd(lanes.weight[t]));
    _mm256_storeu_pd(F + 2 * i, f);
  }
  if (i < hi) {
    if (measure)
      drift_and_start_force<2, true>(i, X, V, F, inv_m, species, exited, k, moved, exits);
    else
      drift_and_start_force<2, false>(i, X, V, F, inv_m, species, exited, k, moved, exits);
  }
  exiting |= exits;
  return moved != 0;
}

/// kick_range<2>() (sp_sweeps.h) two particles at a time where neither is skipped.
[[gnu::target("avx2")]] inline bool kick_range_2d(int lo, int hi, const double* __restrict X, double* __restrict V,
                                                  const double* __restrict F, double half_dt,
                                                  const double* __restrict inv_m,
                                                  const std::uint8_t* __restrict skip) {
  const __m256d h = _mm256_set1_pd(half_dt), zero = _mm256_setzero_pd();
  int bad = 0;
  int i = lo;
  for (; hi - i >= 2; i += 2) {
    if (skip && (skip[i] | skip[i + 1])) {
      for (int j = i; j < i + 2; ++j)
        if (!skip[j]) bad |= not_finite(kick_one<2>(j, X, V, F, half_dt, inv_m));
      continue;
    }
    // c = half_dt / m per particle (as half_dt * inv_m), v += c f
    const __m256d c = _mm256_mul_pd(h, per_particle(inv_m, i));
    const __m256d v = _mm256_add_pd(_mm256_loadu_pd(V + 2 * i), _mm256_mul_pd(c, _mm256_loadu_pd(F + 2 * i)));
    _mm256_storeu_pd(V + 2 * i, v);
    // kick_one's finiteness sum x0 + v0 + (x1 + v1) per particle, and its test t - t == 0
    const __m256d xv = _mm256_add_pd(_mm256_loadu_pd(X + 2 * i), v);
    const __m256d t = _mm256_hadd_pd(xv, xv);
    bad |= _mm256_movemask_pd(_mm256_cmp_pd(_mm256_sub_pd(t, t), zero, _CMP_NEQ_UQ));
  }
  if (i < hi && !(skip && skip[i])) bad |= not_finite(kick_one<2>(i, X, V, F, half_dt, inv_m));
  return bad != 0;
}

}  // namespace beverloo::avx2
#endif

namespace beverloo {

/// The step's drift sweep (ForceField::drift_and_start_forces): two particles at a time in 2D
/// where the processor has AVX2, else drift_range(). The same bits either way.
template <int D>
inline bool step_drift_range(int lo, int hi, double* X, double* V, double* F, const double* inv_m,
                             const std::uint8_t* species, const std::uint8_t* exited, const DriftConstants& k,
                             int& exiting) {
#if defined(BEVERLOO_HAVE_AVX2_SWEEPS)
  if constexpr (D == 2)
    if (avx2::available()) return avx2::drift_range_2d(lo, hi, X, V, F, inv_m, species, exited, k, exiting);
#endif
  return drift_range<D>(lo, hi, X, V, F, inv_m, species, exited, k, exiting);
}

/// The step's kick sweep of a block (SpContact::block_and_kick): as step_drift_range(), with
/// kick_range().
template <int D>
inline bool step_kick_range(int lo, int hi, const double* X, double* V, const double* F, double half_dt,
                            const double* inv_m, const std::uint8_t* skip) {
#if defined(BEVERLOO_HAVE_AVX2_SWEEPS)
  if constexpr (D == 2)
    if (avx2::available()) return avx2::kick_range_2d(lo, hi, X, V, F, half_dt, inv_m, skip);
#endif
  return kick_range<D>(lo, hi, X, V, F, half_dt, inv_m, skip);
}

}  // namespace beverloo
