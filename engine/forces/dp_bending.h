#pragma once
/// \file dp_bending.h
/// \brief DP bending term: U_m = (K_b / (2 n_v l_0^2)) sum_i |u_i - u_next(i)|^2 with
/// u_i = l_i/|l_i| the unit edge vectors. With g_i = dU/du_i = 2C (2 u_i - u_next - u_prev)
/// (C = K_b/(2 n_v l0^2)), the gradient with respect to the edge vector is the part of g_i
/// perpendicular to u_i divided by |l_i|; it pulls the edge's end and pushes its start.
#include <cmath>

#include "../dp/polygons.h"
#include "force_term.h"

namespace beverloo {

class DpBending final : public ForceTerm<2> {
 public:
  DpBending(const PolygonSet& p, const DpShape& shape, double K_b) : p_(p), shape_(shape), k_(K_b) {
    unit_.resize(p.vertices());
    inv_len_.resize(p.vertices());
  }
  std::string_view name() const override { return "dp_bending"; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    if (k_ == 0) return {};
    const int nv = p_.vertices();
    for (int i = 0; i < nv; ++i) {
      const Vec<2> e = s.x[p_.next[i]] - s.x[i];
      inv_len_[i] = 1.0 / e.norm();
      unit_[i] = e * inv_len_[i];
    }
    // C = K_b / (2 n_v l0^2) per species, made once (a division per vertex was a tenth of the term)
    double c_of[2];
    for (int k = 0; k < 2; ++k) c_of[k] = k_ / (2.0 * shape_.n_v * shape_.l0[k] * shape_.l0[k]);
    double energy = 0;
    for (int i = 0; i < nv; ++i) {
      const double c = c_of[s.species[i]];
      const Vec<2>& u = unit_[i];
      energy += c * (u - unit_[p_.next[i]]).squaredNorm();
      const Vec<2> g = (2 * c) * (2 * u - unit_[p_.next[i]] - unit_[p_.prev[i]]);
      const Vec<2> dU_de = (g - g.dot(u) * u) * inv_len_[i];
      f[p_.next[i]] -= dU_de;
      f[i] += dU_de;
    }
    return {energy, 0};
  }

 private:
  const PolygonSet& p_;
  const DpShape& shape_;
  double k_;
  VecArray<2> unit_;
  std::vector<double> inv_len_;
};

}  // namespace beverloo
