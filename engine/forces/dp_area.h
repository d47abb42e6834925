#pragma once
/// \file dp_area.h
/// \brief DP area term: U_m = (K_a/2)(a_m - a_m0)^2 with a_m the shoelace area, so
/// dU/dr_i = K_a (a - a0) (1/2) (y_{i+1} - y_{i-1}, x_{i-1} - x_{i+1}).
#include <array>

#include "../dp/polygons.h"
#include "force_term.h"

namespace beverloo {

class DpArea final : public ForceTerm<2> {
 public:
  /// K_a per species (small, large): a polygon's stiffness is its species'
  DpArea(const PolygonSet& p, const DpShape& shape, std::array<double, 2> K_a) : p_(p), shape_(shape), k_{K_a[0], K_a[1]} {}
  std::string_view name() const override { return "dp_area"; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    double energy = 0;
    for (int m = 0; m < p_.polygons(); ++m) add_polygon(s, f, m, energy);
    return {energy, 0};
  }
  /// Polygon m's part: its forces into f, its energy onto `energy` (DpForceField's fused pass
  /// calls this polygon by polygon, between the other shape terms: each vertex's force sums
  /// the same contributions in the same order as the terms one after another).
  void add_polygon(const ParticleState<2>& s, VecArray<2>& f, int m, double& energy) const {
    const int species = s.species[p_.first[m]];
    const double da = polygon_area(p_, s.x, m) - shape_.a0[species];
    energy += 0.5 * k_[species] * da * da;
    const double c = -0.5 * k_[species] * da;  // force = -dU/dr
    for (int i = p_.first[m]; i < p_.first[m + 1]; ++i) {
      const Vec<2>& xn = s.x[p_.next[i]];
      const Vec<2>& xp = s.x[p_.prev[i]];
      f[i][0] += c * (xn[1] - xp[1]);
      f[i][1] += c * (xp[0] - xn[0]);
    }
  }

 private:
  const PolygonSet& p_;
  const DpShape& shape_;
  double k_[2];
};

}  // namespace beverloo
