#pragma once
/// \file kinetic_friction.h
/// \brief Kinetic friction between overlapping particles (physics.md 3 and 10).
///
/// The paper's text: F_m = -mu (v_m - v_n), on the full relative velocity vector. The authors'
/// code splits the relative velocity dv along the contact normal nhat and the tangent:
///   F_m = -mu_n (dv . nhat) nhat - mu_t (dv - (dv . nhat) nhat),
/// with mu_n = 0 in every production run (docs/authors-model.md). Both forms are pairwise equal
/// and opposite (momentum is conserved) and their power, -mu_n (dv.n)^2 - mu_t |dv_t|^2, is
/// never positive (they only remove energy).
#include "../vec.h"

namespace beverloo {

/// The two coefficients of one contact law. When they are equal the unsplit form is used,
/// which is the same force but keeps the floating-point operations (and results) of the text's
/// model bit for bit.
struct FrictionLaw {
  double mu_n = 0, mu_t = 0;
  bool split() const { return mu_n != mu_t; }
  bool active() const { return mu_n > 0 || mu_t > 0; }
  double largest() const { return mu_n > mu_t ? mu_n : mu_t; }
};

template <int D>
inline Vec<D> kinetic_friction_force(double mu, const Vec<D>& v_m, const Vec<D>& v_n) {
  return -mu * (v_m - v_n);
}

/// The split law on particle m; nhat is the unit contact normal (either sign).
template <int D>
inline Vec<D> kinetic_friction_force(const FrictionLaw& law, const Vec<D>& v_m, const Vec<D>& v_n, const Vec<D>& nhat) {
  const Vec<D> dv = v_m - v_n;
  const Vec<D> dv_n = dv.dot(nhat) * nhat;
  return -law.mu_n * dv_n - law.mu_t * (dv - dv_n);
}

}  // namespace beverloo
