#pragma once
/// \file fire.h
/// \brief FIRE energy minimisation (Bitzek et al., PRL 97, 170201, 2006) on any force field.
/// The caller chooses what is minimised (the hopper protocol switches gravity and dissipation
/// off to remove overlaps).
#include <cmath>
#include <cstdint>

#include "../config.h"
#include "../forces/force_field.h"

namespace beverloo {

struct FireResult {
  bool converged = false;
  std::int64_t iterations = 0;
  double max_force = 0;  ///< largest |F_i| at the end
  double energy = 0;     ///< potential energy at the end
};

/// FF: ForceField<D> or DpForceField.
template <int D, class FF>
FireResult fire_minimize(ParticleState<D>& s, FF& ff, const FireParams& p, double dt0) {
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


}  // namespace beverloo
