#pragma once
/// \file velocity_verlet.h
/// \brief The velocity-Verlet variant of physics.md 5 for velocity-dependent forces:
///   x(t+dt) = x + v dt + a dt^2/2;  v~ = v + a dt/2;  F(t+dt) = F(x(t+dt), v~);
///   v(t+dt) = v~ + a(t+dt) dt/2   (= v + (a(t) + a(t+dt)) dt/2).
/// Without dissipation this is plain velocity Verlet: energy error O(dt^2), no drift.
#include <cmath>
#include <emmintrin.h>

#include "../forces/force_field.h"
#include "sp_sweeps.h"

namespace beverloo {

struct StepReport {
  ForceReport forces;
  bool finite = true;  ///< all positions and velocities finite after the step
};

/// One step. between_drift_and_force(s) runs after the positions are advanced and before the
/// forces are evaluated: where the protocol counts exits and reinjects particles, so that the
/// forces of the step always belong to the final positions.
/// FF is ForceField<D> or DpForceField (anything with ForceReport compute(ParticleState<D>&)).
/// drift()'s operations on 2D item i, both components in one SSE2 register (each lane the
/// scalar operations: the same bits); returns the new position and velocity. Shared by drift()
/// and the DP step's one-pass drift (DpSystem::drift_and_sync).
[[gnu::always_inline]] inline void drift_item_2d(int i, double* __restrict X, double* __restrict V,
                                                 const double* __restrict F, const double* __restrict inv_m,
                                                 __m128d dt, __m128d half_dt, __m128d half_dt2, __m128d& x_out,
                                                 __m128d& v_out) {
  const __m128d a = _mm_mul_pd(_mm_loadu_pd(F + 2 * i), _mm_set1_pd(inv_m[i]));
  const __m128d v = _mm_loadu_pd(V + 2 * i);
  x_out = _mm_add_pd(_mm_loadu_pd(X + 2 * i), _mm_add_pd(_mm_mul_pd(dt, v), _mm_mul_pd(half_dt2, a)));
  v_out = _mm_add_pd(v, _mm_mul_pd(half_dt, a));
  _mm_storeu_pd(X + 2 * i, x_out);
  _mm_storeu_pd(V + 2 * i, v_out);
}

/// The first half of a step: x += v dt + a dt^2/2, v += a dt/2 (a = f / m). Returns the largest
/// squared displacement from `reference` (a Verlet list's build positions; empty: 0), taken in
/// the same pass so that the list's rebuild test costs no second sweep over the positions.
/// threads: OpenMP threads for the loop (each item's update is its own: any count, same bits).
/// Raw pointers and component loops: through the vectors' members GCC reloaded every array
/// pointer on every item (the stores might alias them). The operations are Eigen's, in its order.
template <int D>
double drift(ParticleState<D>& s, double dt, const VecArray<D>& reference, int threads = 1) {
  const double half_dt = 0.5 * dt, half_dt2 = 0.5 * dt * dt;
  const int n = s.size();
  double* __restrict X = s.x.data()->data();
  double* __restrict V = s.v.data()->data();
  const double* __restrict F = s.f.data()->data();
  const double* __restrict inv_m = s.inv_mass.data();
  const bool measure = static_cast<int>(reference.size()) == n;
  const double* __restrict R = measure ? reference.data()->data() : nullptr;
  // one item: the update and its squared displacement from the reference (into moved2, a max)
  auto one = [&](int i, double& moved2) {
    double d2 = 0;
    for (int d = 0; d < D; ++d) {
      const double a = F[i * D + d] * inv_m[i];
      X[i * D + d] += dt * V[i * D + d] + half_dt2 * a;
      V[i * D + d] += half_dt * a;
    }
    if (measure) {
      for (int d = 0; d < D; ++d) {
        const double u = X[i * D + d] - R[i * D + d];
        d2 = d == 0 ? u * u : d2 + u * u;
      }
      moved2 = d2 > moved2 ? d2 : moved2;
    }
  };
  double moved2 = 0;
  if (threads == 1 && !measure) {
    // the same operations as one() without the measure, in a loop of its own: through the
    // lambda's captured references GCC kept every item scalar and reloaded dt from the stack
    if constexpr (D == 2) {
      const __m128d vdt = _mm_set1_pd(dt), vh = _mm_set1_pd(half_dt), vh2 = _mm_set1_pd(half_dt2);
      __m128d x, v;
      for (int i = 0; i < n; ++i) drift_item_2d(i, X, V, F, inv_m, vdt, vh, vh2, x, v);
      return 0;
    }
    for (int i = 0; i < n; ++i) {
      const double im = inv_m[i];
      for (int d = 0; d < D; ++d) {
        const double a = F[i * D + d] * im;
        X[i * D + d] += dt * V[i * D + d] + half_dt2 * a;
        V[i * D + d] += half_dt * a;
      }
    }
    return 0;
  }
  if (threads == 1) {  // no parallel region: even a team of one costs per call in libgomp
    for (int i = 0; i < n; ++i) one(i, moved2);
  } else {
#pragma omp parallel for schedule(static) reduction(max : moved2) num_threads(threads)
    for (int i = 0; i < n; ++i) one(i, moved2);
  }
  return moved2;
}

/// The second half: v += f dt / (2 m) with the new forces. Returns whether every position and
/// velocity is finite (NaN or inf anywhere poisons one running sum: one add per component).
template <int D>
bool kick(ParticleState<D>& s, double dt, int threads = 1) {
  const double half_dt = 0.5 * dt;
  const int n = s.size();
  const double* __restrict X = s.x.data()->data();
  double* __restrict V = s.v.data()->data();
  const double* __restrict F = s.f.data()->data();
  const double* __restrict inv_m = s.inv_mass.data();
  if (threads == 1) return !kick_range<D>(0, n, X, V, F, half_dt, inv_m, nullptr);  // no parallel region
  int bad = 0;
#pragma omp parallel for schedule(static) reduction(| : bad) num_threads(threads)
  for (int c = 0; c < threads; ++c)
    bad |= kick_range<D>(int(long(n) * c / threads), int(long(n) * (c + 1) / threads), X, V, F, half_dt, inv_m, nullptr);
  return bad == 0;
}

/// threads: for the drift and the kick (each item's update is its own: any count, same bits).
template <int D, class FF, class Hook>
StepReport velocity_verlet_step(ParticleState<D>& s, FF& ff, double dt, Hook&& between_drift_and_force,
                                int threads = 1) {
  static const VecArray<D> kNoReference;
  drift(s, dt, kNoReference, threads);
  between_drift_and_force(s);  // may take items out (a draining hopper): the kick counts them again
  StepReport r;
  r.forces = ff.compute(s);
  r.finite = kick(s, dt, threads);
  ++s.step;
  return r;
}

template <int D, class FF>
StepReport velocity_verlet_step(ParticleState<D>& s, FF& ff, double dt) {
  return velocity_verlet_step(s, ff, dt, [](ParticleState<D>&) {});
}

}  // namespace beverloo
