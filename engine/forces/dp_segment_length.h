#pragma once
/// \file dp_segment_length.h
/// \brief DP perimeter term: U_m = (K_l n_v / 2) sum_i (|l_i| - l_0)^2 over the edges
/// l_i = r_next(i) - r_i: a harmonic spring of stiffness K_l n_v along each edge.
/// Also records the longest edge, which bounds the smooth contact's Verlet-list reach.
#include <array>

#include "../dp/polygons.h"
#include "dp_polygon_edges.h"
#include "force_term.h"

namespace beverloo {

class DpSegmentLength final : public ForceTerm<2> {
 public:
  /// K_l per species (small, large): an edge's stiffness is its polygon's
  DpSegmentLength(const PolygonSet& p, const DpShape& shape, std::array<double, 2> K_l)
      : p_(p), shape_(shape), k_{K_l[0] * shape.n_v, K_l[1] * shape.n_v} {}
  std::string_view name() const override { return "dp_segment_length"; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    double energy = 0, longest = 0;
    for (int m = 0; m < p_.polygons(); ++m) {
      edges_.measure(p_, s, m);
      add_polygon(f, edges_, energy, longest);
    }
    longest_ = longest;
    return {energy, 0};
  }
  /// Per edge k of the measured polygon: the force on its end vertex into edges.seg_fx/fy (its
  /// start takes minus it), its energy into edges.seg_u.
  void edge_forces(PolygonEdges& edges) const {
    const int n = edges.count;
    const double k = k_[edges.species], l0 = shape_.l0[edges.species];
    const double* ex = edges.ex;
    const double* ey = edges.ey;
    const double* len = edges.len;
    double* __restrict fx = edges.seg_fx;
    double* __restrict fy = edges.seg_fy;
    double* __restrict u = edges.seg_u;
    #pragma omp simd  // element-wise: the same operations per edge as the scalar loop
    for (int e = 0; e < n; ++e) {
      const double stretch = len[e] - l0;
      u[e] = 0.5 * k * stretch * stretch;
      const double along = -k * stretch / len[e];  // toward l0
      fx[e] = along * ex[e];
      fy[e] = along * ey[e];
    }
  }
  /// The measured polygon's part: its forces added to f (edge by edge, end vertex then start),
  /// its energy onto `energy`, its longest edge into `longest` (a running maximum). See
  /// DpArea::add_polygon for why per polygon.
  void add_polygon(VecArray<2>& f, PolygonEdges& edges, double& energy, double& longest) const {
    edge_forces(edges);
    const int first = edges.first, n = edges.count;
    for (int e = 0; e < n; ++e) {
      const int i = first + e, j = p_.next[i];
      energy += edges.seg_u[e];
      f[j][0] += edges.seg_fx[e];
      f[j][1] += edges.seg_fy[e];
      f[i][0] -= edges.seg_fx[e];
      f[i][1] -= edges.seg_fy[e];
      longest = edges.len[e] > longest ? edges.len[e] : longest;
    }
  }
  double longest_edge() const { return longest_; }
  /// K_l of a species (the lane kernel reads the constants it uses)
  double stiffness(int species) const { return k_[species]; }
  /// For a pass over the polygons that calls add_polygon itself.
  void set_longest_edge(double longest) { longest_ = longest; }

 private:
  const PolygonSet& p_;
  const DpShape& shape_;
  double k_[2];
  double longest_ = 0;
  PolygonEdges edges_;  ///< accumulate()'s own scratch
};

}  // namespace beverloo
