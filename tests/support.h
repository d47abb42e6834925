#pragma once
// Helpers shared by the tests: small systems in small hoppers.
#include <cmath>

#include "engine/config.h"
#include "engine/forces/force_field.h"
#include "engine/geometry/make_hopper.h"
#include "engine/integrate/fire.h"
#include "engine/protocol/placement.h"
#include "engine/rng.h"
#include "engine/units.h"

namespace beverloo::testing {

inline SimConfig small_config(int dim, int n, double w, double zeta = 0, double mu = 0) {
  SimConfig c;
  c.dimension = dim;
  c.N = n;
  c.W = dim == 2 ? 12 : 8;
  c.w = w;
  c.zeta = zeta;
  c.mu = mu;
  c.seed = 7;
  c.resolve_and_validate();
  return c;
}

template <int D>
Hopper<D> hopper_for(const SimConfig& c) {
  return make_hopper<D>(c);
}

/// N particles placed at random (dense: overlaps remain unless minimised).
/// A small (0) and a large (1) particle of c's mixture, at rest, positions to be set.
template <int D>
ParticleState<D> small_and_large(const SimConfig& c) {
  ParticleState<D> s;
  s.sp = Species::bidisperse(D, c.size_ratio);
  s.resize(2);
  s.species = {0, 1};
  for (int k = 0; k < 2; ++k) s.inv_mass[k] = 1 / s.mass(k);
  return s;
}

template <int D>
ParticleState<D> random_state(const SimConfig& c, const Hopper<D>& h, std::uint64_t seed) {
  ParticleState<D> s;
  Rng rng(seed);
  SimConfig dense = c;
  dense.initial_packing_fraction = 0.6;
  place_randomly(s, dense, h, rng);
  return s;
}

template <int D>
void random_velocities(ParticleState<D>& s, std::uint64_t seed, double scale = 1.0) {
  Rng rng(seed);
  for (auto& v : s.v)
    for (int d = 0; d < D; ++d) v[d] = scale * rng.uniform(-1, 1);
}

}  // namespace beverloo::testing
