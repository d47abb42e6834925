#pragma once
// Helpers for the DP tests: a few polygons, regular or randomly deformed, in a small hopper.
#include "engine/dp/dp_force_field.h"
#include "engine/dp/polygons.h"
#include "support.h"

namespace beverloo::testing {

inline SimConfig dp_config(const std::string& model, int n, double zeta = 0, double mu = 0) {
  SimConfig c;
  c.model = model;
  c.dimension = 2;
  c.N = n;
  c.W = 12;
  c.w = 3;
  c.zeta = zeta;
  c.mu = mu;
  c.seed = 7;
  c.resolve_and_validate();
  return c;
}

/// Vertex state of n polygons, species alternating, at the given centres; each vertex is moved
/// by up to `jitter` l0 at random (0: regular polygons).
struct DpFixture {
  SimConfig c;
  DpShape shape;
  PolygonSet poly;
  ParticleState<2> verts;

  DpFixture(const SimConfig& config, const std::vector<Vec<2>>& centres, double jitter, std::uint64_t seed)
      : c(config), shape(DpShape::from_config(config)), poly(PolygonSet::uniform(int(centres.size()), config.dp.n_v)) {
    const auto diam = DpForceField::list_diameters(shape);
    verts.sp.sigma = {diam[0], diam[1]};
    verts.sp.mass = {shape.vertex_mass[0], shape.vertex_mass[1]};
    verts.sp.ref_size = {shape.a0[0], shape.a0[1]};
    verts.resize(poly.vertices());
    Rng rng(seed);
    for (int m = 0; m < poly.polygons(); ++m) {
      for (int i = poly.first[m]; i < poly.first[m + 1]; ++i) {
        verts.species[i] = std::uint8_t(m % 2);
        verts.inv_mass[i] = 1.0 / shape.vertex_mass[m % 2];
      }
      place_regular_polygon(poly, shape, verts, m, centres[m], rng.uniform(0, 1), Vec<2>::Zero());
      for (int i = poly.first[m]; i < poly.first[m + 1]; ++i)
        verts.x[i] += jitter * shape.l0[m % 2] * Vec<2>(rng.uniform(-1, 1), rng.uniform(-1, 1));
    }
  }
};

}  // namespace beverloo::testing
