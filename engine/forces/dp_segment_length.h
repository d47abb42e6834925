#pragma once
/// \file dp_segment_length.h
/// \brief DP perimeter term: U_m = (K_l n_v / 2) sum_i (|l_i| - l_0)^2 over the edges
/// l_i = r_next(i) - r_i: a harmonic spring of stiffness K_l n_v along each edge.
/// Also records the longest edge, which bounds the smooth contact's Verlet-list reach.
#include <array>
#include <cmath>

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
      edges_.measure(p_, s.x, m);
      add_polygon(s, f, edges_, energy, longest);
    }
    longest_ = longest;
    return {energy, 0};
  }
  /// The measured polygon's part: its forces into f, its energy onto `energy`, its longest edge
  /// into `longest` (a running maximum). See DpArea::add_polygon for why per polygon.
  void add_polygon(const ParticleState<2>& s, VecArray<2>& f, const PolygonEdges& edges, double& energy,
                   double& longest) const {
    const int first = edges.first, n = edges.count;
    for (int k = 0; k < n; ++k) {
      const int i = first + k, j = p_.next[i];
      const Vec<2>& e = edges.e[k];
      const double len = edges.len[k];
      const int species = s.species[i];
      const double stretch = len - shape_.l0[species];
      energy += 0.5 * k_[species] * stretch * stretch;
      const Vec<2> fj = (-k_[species] * stretch / len) * e;  // on the end vertex, toward l0
      f[j] += fj;
      f[i] -= fj;
      longest = len > longest ? len : longest;
    }
  }
  double longest_edge() const { return longest_; }
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
