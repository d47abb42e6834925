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
  bool active() const { return on_ && (c_[0] != 0 || c_[1] != 0); }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    if (!active()) return {};
    double power = 0;
    const int n = s.size();
    for (int i = 0; i < n; ++i) power += add_to(s, i, f[i]);
    return {0, power};
  }
  /// The drag on item i added to fi; returns its power -c |v|^2 (<= 0).
  double add_to(const ParticleState<D>& s, int i, Vec<D>& fi) const {
    add_force(s, i, fi);
    return power(s, i);
  }
  /// add_to() in its two halves, for a sweep that adds the force later than it sums the power.
  void add_force(const ParticleState<D>& s, int i, Vec<D>& fi) const { fi -= c_[s.species[i]] * s.v[i]; }
  double power(const ParticleState<D>& s, int i) const { return -c_[s.species[i]] * s.v[i].squaredNorm(); }

 private:
  std::array<double, 2> c_;
  bool on_ = true;
};

}  // namespace beverloo
