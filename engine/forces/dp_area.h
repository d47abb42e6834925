#pragma once
/// \file dp_area.h
/// \brief DP area term: U_m = (K_a/2)(a_m - a_m0)^2 with a_m the shoelace area, so
/// dU/dr_i = K_a (a - a0) (1/2) (y_{i+1} - y_{i-1}, x_{i-1} - x_{i+1}).
#include <array>

#include "../dp/polygons.h"
#include "dp_polygon_edges.h"
#include "force_term.h"

namespace beverloo {

class DpArea final : public ForceTerm<2> {
 public:
  /// K_a per species (small, large): a polygon's stiffness is its species'
  DpArea(const PolygonSet& p, const DpShape& shape, std::array<double, 2> K_a) : p_(p), shape_(shape), k_{K_a[0], K_a[1]} {}
  std::string_view name() const override { return "dp_area"; }
  /// K_a of a species (the lane kernel reads the constants it uses)
  double stiffness(int species) const { return k_[species]; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override {
    double energy = 0;
    for (int m = 0; m < p_.polygons(); ++m) {
      edges_.measure(p_, s, m);
      add_polygon(f, edges_, energy);
    }
    return {energy, 0};
  }
  /// The measured polygon's area force on each vertex into edges.area_fx/fy; returns its energy.
  /// The area is polygon_area()'s sum, in its order.
  double vertex_forces(PolygonEdges& edges) const {
    const int n = edges.count;
    const double* x = edges.x;
    const double* y = edges.y;
    double twice_area = 0;
    for (int k = 0; k < n; ++k) twice_area += x[k] * y[k + 1] - x[k + 1] * y[k];
    const double da = 0.5 * twice_area - shape_.a0[edges.species];
    const double c = -0.5 * k_[edges.species] * da;  // force = -dU/dr
    double* __restrict fx = edges.area_fx;
    double* __restrict fy = edges.area_fy;
    for (int k = 0; k < n; ++k) {
      fx[k] = c * (y[k + 1] - y[k - 1]);
      fy[k] = c * (x[k - 1] - x[k + 1]);
    }
    return 0.5 * k_[edges.species] * da * da;
  }
  /// The measured polygon's part: its forces added to f, its energy onto `energy`. Per polygon
  /// so that DpForceField's fused pass can take the terms polygon by polygon: each vertex's
  /// force sums the same contributions in the same order as the terms one after another.
  void add_polygon(VecArray<2>& f, PolygonEdges& edges, double& energy) const {
    energy += vertex_forces(edges);
    for (int k = 0; k < edges.count; ++k) {
      f[edges.first + k][0] += edges.area_fx[k];
      f[edges.first + k][1] += edges.area_fy[k];
    }
  }

 private:
  const PolygonSet& p_;
  const DpShape& shape_;
  double k_[2];
  PolygonEdges edges_;  ///< accumulate()'s own scratch
};

}  // namespace beverloo
