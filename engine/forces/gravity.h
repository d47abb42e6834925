#pragma once
/// \file gravity.h
/// \brief Gravity along -y (2D) or -z (3D): U = M g h, F = -M g e_up.
#include "force_term.h"

namespace beverloo {

template <int D>
class Gravity final : public ForceTerm<D> {
 public:
  explicit Gravity(double g) : g_(g) {}
  std::string_view name() const override { return "gravity"; }
  void set_g(double g) { g_ = g; }
  double g() const { return g_; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    if (g_ == 0) return {};
    double energy = 0;
    const int n = s.size();
    for (int i = 0; i < n; ++i) energy += add_to(s, i, f[i]);
    return {energy, 0};
  }
  /// Gravity on item i added to fi; returns its energy M g h.
  double add_to(const ParticleState<D>& s, int i, Vec<D>& fi) const {
    add_force(s, i, fi);
    return energy(s, i);
  }
  /// add_to() in its two halves, for a sweep that adds the force later than it sums the energy.
  void add_force(const ParticleState<D>& s, int i, Vec<D>& fi) const { fi[kUp<D>] -= s.mass(i) * g_; }
  double energy(const ParticleState<D>& s, int i) const { return s.mass(i) * g_ * s.x[i][kUp<D>]; }

 private:
  double g_;
};

}  // namespace beverloo
