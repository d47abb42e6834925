#include "fire.h"

#include <cmath>

namespace beverloo {

template <int D>
FireResult fire_minimize(ParticleState<D>& s, ForceField<D>& ff, const FireParams& p, double dt0) {
  const int n = s.size();
  for (auto& v : s.v) v.setZero();
  double dt = dt0, alpha = p.alpha0;
  const double dt_max = p.dt_max_factor * dt0;
  int n_positive = 0;
  FireResult res;
  ForceReport rep = ff.compute(s);
  for (res.iterations = 0; res.iterations < p.max_iter; ++res.iterations) {
    double power = 0, v2 = 0, f2 = 0, fmax2 = 0;
    for (int i = 0; i < n; ++i) {
      power += s.f[i].dot(s.v[i]);
      v2 += s.v[i].squaredNorm();
      const double fi2 = s.f[i].squaredNorm();
      f2 += fi2;
      fmax2 = fi2 > fmax2 ? fi2 : fmax2;
    }
    res.max_force = std::sqrt(fmax2);
    if (res.max_force < p.force_tol) {
      res.converged = true;
      break;
    }
    if (power > 0) {
      // mix the velocity toward the force direction
      const double scale = f2 > 0 ? alpha * std::sqrt(v2 / f2) : 0;
      for (int i = 0; i < n; ++i) s.v[i] = (1 - alpha) * s.v[i] + scale * s.f[i];
      if (++n_positive > p.n_min) {
        dt = std::min(dt * p.f_inc, dt_max);
        alpha *= p.f_alpha;
      }
    } else {
      n_positive = 0;
      dt *= p.f_dec;
      alpha = p.alpha0;
      for (auto& v : s.v) v.setZero();
    }
    // semi-implicit Euler MD step
    for (int i = 0; i < n; ++i) {
      s.v[i] += dt * s.inv_mass[i] * s.f[i];
      s.x[i] += dt * s.v[i];
    }
    rep = ff.compute(s);
  }
  for (auto& v : s.v) v.setZero();
  rep = ff.compute(s);
  res.energy = rep.potential();
  return res;
}

template FireResult fire_minimize<2>(ParticleState<2>&, ForceField<2>&, const FireParams&, double);
template FireResult fire_minimize<3>(ParticleState<3>&, ForceField<3>&, const FireParams&, double);

}  // namespace beverloo
