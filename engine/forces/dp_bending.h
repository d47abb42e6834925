#pragma once
/// \file dp_bending.h
/// \brief DP bending term: U_m = (K_b / (2 n_v l_0^2)) sum_i |u_i - u_next(i)|^2 with
/// u_i = l_i/|l_i| the unit edge vectors. With g_i = dU/du_i = 2C (2 u_i - u_next - u_prev)
/// (C = K_b/(2 n_v l0^2)), the gradient with respect to the edge vector is the part of g_i
/// perpendicular to u_i divided by |l_i|; it pulls the edge's end and pushes its start.
#include <cmath>

#include "../dp/polygons.h"
#include "dp_polygon_edges.h"
#include "force_term.h"

namespace beverloo {

class DpBending final : public ForceTerm<2> {
 public:
  DpBending(const PolygonSet& p, const DpShape& shape, double K_b) : p_(p), k_(K_b) {
    // C = K_b / (2 n_v l0^2) per species, made once (a division per vertex was a tenth of the term)
    for (int k = 0; k < 2; ++k) c_of_[k] = k_ / (2.0 * shape.n_v * shape.l0[k] * shape.l0[k]);
  }
  std::string_view name() const override { return "dp_bending"; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    double energy = 0;
    for (int m = 0; k_ != 0 && m < p_.polygons(); ++m) {
      edges_.measure(p_, s.x, m);
      add_polygon(s, f, edges_, energy);
    }
    return {energy, 0};
  }
  /// The measured polygon's part: its forces into f, its energy onto `energy`. See
  /// DpArea::add_polygon for why per polygon. Uses edges' scratch (unit, inv_len): const, so
  /// threads with their own PolygonEdges may call it for different polygons at once.
  void add_polygon(const ParticleState<2>& s, VecArray<2>& f, PolygonEdges& edges, double& energy) const {
    if (k_ == 0) return;
    const int first = edges.first, n = edges.count;
    VecArray<2>& unit_ = edges.unit;
    std::vector<double>& inv_len_ = edges.inv_len;
    for (int k = 0; k < n; ++k) {
      inv_len_[k] = 1.0 / edges.len[k];
      unit_[k] = edges.e[k] * inv_len_[k];
    }
    for (int k = 0; k < n; ++k) {
      const int i = first + k;
      const double c = c_of_[s.species[i]];
      const Vec<2>& u = unit_[k];
      const Vec<2>& u_next = unit_[p_.next[i] - first];
      const Vec<2>& u_prev = unit_[p_.prev[i] - first];
      energy += c * (u - u_next).squaredNorm();
      const Vec<2> g = (2 * c) * (2 * u - u_next - u_prev);
      const Vec<2> dU_de = (g - g.dot(u) * u) * inv_len_[k];
      f[p_.next[i]] -= dU_de;
      f[i] += dU_de;
    }
  }

 private:
  const PolygonSet& p_;
  double k_;
  double c_of_[2];
  PolygonEdges edges_;           ///< accumulate()'s own scratch
};

}  // namespace beverloo
