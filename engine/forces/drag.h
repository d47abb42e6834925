#pragma once
/// \file drag.h
/// \brief Viscous drag from the background fluid, F_i = -c_i v_i with power -c_i |v_i|^2 <= 0.
///
/// The coefficient per particle (or vertex) depends on its species only: zeta (the paper's
/// text, the same for every particle; DP: zeta/n_v per vertex) plus drag_rate times the mass
/// (the authors' code, F = -b M v: light and heavy particles reach the same terminal-velocity
/// time 1/b). drag_coefficients() builds the pair of coefficients once.
#include <array>

#include "force_term.h"

namespace beverloo {

/// c_species = zeta_per_body + rate * mass_species (one entry per species, small and large).
inline std::array<double, 2> drag_coefficients(double zeta_per_body, double rate, const std::array<double, 2>& mass) {
  return {zeta_per_body + rate * mass[0], zeta_per_body + rate * mass[1]};
}

template <int D>
class Drag final : public ForceTerm<D> {
 public:
  explicit Drag(std::array<double, 2> coefficient) : c_(coefficient) {}
  std::string_view name() const override { return "drag"; }
  void set_enabled(bool on) { on_ = on; }
  /// The coefficient of a species (force per velocity).
  double coefficient(int species) const { return c_[species]; }
  const std::array<double, 2>& coefficients() const { return c_; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    if (!on_ || (c_[0] == 0 && c_[1] == 0)) return {};
    double power = 0;
    const int n = s.size();
    if (c_[0] == c_[1]) {  // one coefficient (zeta alone): no per-particle lookup in this loop
      const double c = c_[0];
      for (int i = 0; i < n; ++i) {
        f[i] -= c * s.v[i];
        power -= c * s.v[i].squaredNorm();
      }
      return {0, power};
    }
    for (int i = 0; i < n; ++i) {
      const double c = c_[s.species[i]];
      f[i] -= c * s.v[i];
      power -= c * s.v[i].squaredNorm();
    }
    return {0, power};
  }

 private:
  std::array<double, 2> c_;
  bool on_ = true;
};

}  // namespace beverloo
