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
      edges_.measure(p_, s, m);
      add_polygon(f, edges_, energy);
    }
    return {energy, 0};
  }
  bool active() const { return k_ != 0; }
  /// The per-edge constant c of a species, K_b / (2 n_v l0^2) (the lane kernel reads it)
  double edge_constant(int species) const { return c_of_[species]; }
  /// Per edge k of the measured polygon: dU/de_k into edges.bend_dx/dy, edge k's energy with its next edge into edges.bend_u; on the way the unit
  /// vectors and inverse lengths (edges.ux, uy, inv_len). Only when active().
  void edge_gradients(PolygonEdges& edges) const {
    const int n = edges.count;
    const double c = c_of_[edges.species], two_c = 2 * c;
    const double* ex = edges.ex;
    const double* ey = edges.ey;
    const double* len = edges.len;
    double* __restrict inv = edges.inv_len;
    double* __restrict ux = edges.ux;
    double* __restrict uy = edges.uy;
    #pragma omp simd  // element-wise: the same operations per edge as the scalar loop
    for (int e = 0; e < n; ++e) {
      inv[e] = 1.0 / len[e];
      ux[e] = ex[e] * inv[e];
      uy[e] = ey[e] * inv[e];
    }
    ux[-1] = ux[n - 1];
    uy[-1] = uy[n - 1];
    ux[n] = ux[0];
    uy[n] = uy[0];
    double* __restrict dx = edges.bend_dx;
    double* __restrict dy = edges.bend_dy;
    double* __restrict u = edges.bend_u;
    #pragma omp simd  // element-wise: the same operations per edge as the scalar loop
    for (int e = 0; e < n; ++e) {
      const double tx = ux[e] - ux[e + 1], ty = uy[e] - uy[e + 1];
      u[e] = c * (tx * tx + ty * ty);
      const double gx = two_c * (2 * ux[e] - ux[e + 1] - ux[e - 1]);
      const double gy = two_c * (2 * uy[e] - uy[e + 1] - uy[e - 1]);
      const double g_along = gx * ux[e] + gy * uy[e];
      dx[e] = (gx - g_along * ux[e]) * inv[e];
      dy[e] = (gy - g_along * uy[e]) * inv[e];
    }
  }
  /// The measured polygon's part: its forces added to f (edge by edge, end vertex then start),
  /// its energy onto `energy`. See DpArea::add_polygon for why per polygon.
  void add_polygon(VecArray<2>& f, PolygonEdges& edges, double& energy) const {
    if (k_ == 0) return;
    edge_gradients(edges);
    const int first = edges.first, n = edges.count;
    for (int e = 0; e < n; ++e) {
      const int i = first + e, j = p_.next[i];
      energy += edges.bend_u[e];
      f[j][0] -= edges.bend_dx[e];
      f[j][1] -= edges.bend_dy[e];
      f[i][0] += edges.bend_dx[e];
      f[i][1] += edges.bend_dy[e];
    }
  }

 private:
  const PolygonSet& p_;
  double k_;
  double c_of_[2];
  PolygonEdges edges_;  ///< accumulate()'s own scratch
};

}  // namespace beverloo
