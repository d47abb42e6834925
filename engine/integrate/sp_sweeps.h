#pragma once
/// \file sp_sweeps.h
/// \brief The per-particle work of the SP step's two sweeps (ForceField::drift_and_start_forces,
/// SpContact::block_and_kick), one particle at a time: the drift with the displacement and
/// exit tests and the start of the new force, and the kick.
///
/// The operations are those of drift(), ForceField::evaluate()'s force start and kick() (in
/// velocity_verlet.h and force_field.h), in their order, so the results are their bits
/// (tests/physics/test_fused_step.cpp). In 2D a particle's two components sit in one SSE2
/// register: the same IEEE operations per component, in about half the instructions (every
/// x86-64 has SSE2: no host tuning, the same bits on every node).
#include <array>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../vec.h"
#include "exit_watch.h"

namespace beverloo {

/// What the drift sweep needs beside the particle arrays.
struct DriftConstants {
  double dt = 0, half_dt = 0, half_dt2 = 0;
  const double* reference = nullptr;  ///< the list's build positions (D per particle); null: no test
  double limit2 = 0;                  ///< the squared displacement that calls for a rebuild
  ExitWatch watch;
  /// Per species: the drag coefficient c and the weight m g (the force start -c v - m g e_up;
  /// the weight as the product evaluate() forms, made once here and not per particle).
  std::array<double, 2> drag{}, weight{};
  void set_force_start(double g, const std::array<double, 2>& drag_coefficients, const std::array<double, 2>& mass) {
    drag = drag_coefficients;
    for (int sp = 0; sp < 2; ++sp) weight[sp] = mass[sp] * g;
  }
};

/// Particle i's force start: f = -c v (drag) - w e_up (its weight w = m g), as evaluate() starts it.
template <int D>
[[gnu::always_inline]] inline void start_force(int i, const double* V, double* F, double c, double weight) {
  for (int d = 0; d < D; ++d) F[i * D + d] = -c * V[i * D + d];
  F[i * D + kUp<D>] -= weight;
}

/// Whether t, a sum of positions and velocities (kick_one()), is not finite: t - t is 0 for a
/// finite t, NaN else.
inline bool not_finite(double t) { return !(t - t == 0); }

/// Particle i: x += v dt + a dt^2/2, v += a dt/2 (a = f/m); whether it moved beyond limit2 from
/// its reference into moved (an or, not a running max: a max is a 4-cycle chain per particle);
/// whether the exit bookkeeping has work for it into exiting; then f = -c v - m g e_up (drag and
/// gravity at the new x and v).
template <int D, bool kMeasure = true>
[[gnu::always_inline]] inline void drift_and_start_force(int i, double* X, double* V, double* F, const double* inv_m,
                                                         const std::uint8_t* species, const std::uint8_t* exited,
                                                         const DriftConstants& k, int& moved, int& exiting) {
  const int sp = species[i];
#if defined(__SSE2__)
  if constexpr (D == 2) {
    const __m128d a = _mm_mul_pd(_mm_loadu_pd(F + 2 * i), _mm_set1_pd(inv_m[i]));
    const __m128d v = _mm_loadu_pd(V + 2 * i);
    const __m128d x = _mm_add_pd(_mm_loadu_pd(X + 2 * i),
                                 _mm_add_pd(_mm_mul_pd(_mm_set1_pd(k.dt), v), _mm_mul_pd(_mm_set1_pd(k.half_dt2), a)));
    const __m128d v_new = _mm_add_pd(v, _mm_mul_pd(_mm_set1_pd(k.half_dt), a));
    _mm_storeu_pd(X + 2 * i, x);
    _mm_storeu_pd(V + 2 * i, v_new);
    if (kMeasure && k.reference) {
      const __m128d u = _mm_sub_pd(x, _mm_loadu_pd(k.reference + 2 * i));
      const __m128d uu = _mm_mul_pd(u, u);
      const double d2 = _mm_cvtsd_f64(_mm_add_sd(uu, _mm_unpackhi_pd(uu, uu)));  // u0^2 + u1^2
      moved |= d2 > k.limit2;
    }
    const double h = _mm_cvtsd_f64(_mm_unpackhi_pd(x, x));
    exiting |= exited[i] ? h < k.watch.exited_below[sp] : !(h >= 0);  // ExitCounter's tests
    // (-c v0, -c v1 - m g): the lane without gravity subtracts +0, which leaves -c v0 as it is
    const __m128d f = _mm_sub_pd(_mm_mul_pd(_mm_set1_pd(-k.drag[sp]), v_new), _mm_set_pd(k.weight[sp], 0.0));
    _mm_storeu_pd(F + 2 * i, f);
    return;
  }
#endif
  for (int d = 0; d < D; ++d) {
    const double a = F[i * D + d] * inv_m[i];
    X[i * D + d] += k.dt * V[i * D + d] + k.half_dt2 * a;
    V[i * D + d] += k.half_dt * a;
  }
  if (kMeasure && k.reference) {
    double d2 = 0;
    for (int d = 0; d < D; ++d) {
      const double u = X[i * D + d] - k.reference[i * D + d];
      d2 = d == 0 ? u * u : d2 + u * u;
    }
    moved |= d2 > k.limit2;
  }
  const double h = X[i * D + kUp<D>];
  exiting |= exited[i] ? h < k.watch.exited_below[sp] : !(h >= 0);  // ExitCounter's tests
  start_force<D>(i, V, F, k.drag[sp], k.weight[sp]);
}

/// drift_and_start_force() over particles lo .. hi - 1; returns whether one moved beyond
/// k.limit2. The constants by value and the arrays restrict: through references (an OpenMP
/// loop's shared variables) the compiler reloaded every constant on every particle.
template <int D>
inline bool drift_range(int lo, int hi, double* __restrict X, double* __restrict V, double* __restrict F,
                        const double* __restrict inv_m, const std::uint8_t* __restrict species,
                        const std::uint8_t* __restrict exited, const DriftConstants k, int& exiting) {
  int moved = 0, exits = 0;
  // the reference test decided once, not per particle
  if (k.reference)
    for (int i = lo; i < hi; ++i) drift_and_start_force<D, true>(i, X, V, F, inv_m, species, exited, k, moved, exits);
  else
    for (int i = lo; i < hi; ++i) drift_and_start_force<D, false>(i, X, V, F, inv_m, species, exited, k, moved, exits);
  exiting |= exits;
  return moved != 0;
}

/// Particle i's kick v += (dt/2 / m) f; returns the sum of its x and v components, finite if
/// and only if they all are (unless near overflow, 1e308).
template <int D>
[[gnu::always_inline]] inline double kick_one(int i, const double* X, double* V, const double* F, double half_dt,
                                              const double* inv_m) {
  const double c = half_dt * inv_m[i];
#if defined(__SSE2__)
  if constexpr (D == 2) {
    const __m128d v = _mm_add_pd(_mm_loadu_pd(V + 2 * i), _mm_mul_pd(_mm_set1_pd(c), _mm_loadu_pd(F + 2 * i)));
    _mm_storeu_pd(V + 2 * i, v);
    const __m128d xv = _mm_add_pd(_mm_loadu_pd(X + 2 * i), v);
    return _mm_cvtsd_f64(xv) + _mm_cvtsd_f64(_mm_unpackhi_pd(xv, xv));
  }
#endif
  double sum = 0;
  for (int d = 0; d < D; ++d) {
    V[i * D + d] += c * F[i * D + d];
    sum += X[i * D + d] + V[i * D + d];
  }
  return sum;
}

/// kick_one() over particles lo .. hi - 1 but those with skip[i] set (skip may be null);
/// returns whether a position or velocity is not finite. An or per particle (not_finite()),
/// not a running sum: a sum is a 4-cycle chain through every particle.
template <int D>
inline bool kick_range(int lo, int hi, const double* __restrict X, double* __restrict V, const double* __restrict F,
                       double half_dt, const double* __restrict inv_m, const std::uint8_t* __restrict skip) {
  int bad = 0;
  for (int i = lo; i < hi; ++i) {
    if (skip && skip[i]) continue;
    const double t = kick_one<D>(i, X, V, F, half_dt, inv_m);
    bad |= not_finite(t);
  }
  return bad != 0;
}

}  // namespace beverloo
