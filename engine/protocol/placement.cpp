#include "placement.h"

#include <cmath>

#include "../units.h"

namespace beverloo {

template <int D>
void place_randomly(ParticleState<D>& s, const SimConfig& c, const Hopper<D>& hopper, Rng& rng) {
  s.sp = Species::bidisperse(D, c.size_ratio);
  s.resize(c.N);
  for (int i = 0; i < c.N; ++i) {
    s.species[i] = i < c.N / 2 ? 0 : 1;
    s.inv_mass[i] = 1.0 / s.sp.mass[s.species[i]];
  }
  // A region above the funnel holding the particles at the initial packing fraction.
  const double r_max = 0.5 * s.sp.sigma[1];
  const double half = hopper.half_width() - r_max;
  const double cross_section = D == 2 ? 2 * half : units::pi * half * half;
  const double height = c.N * s.sp.mean_ref_size() / c.initial_packing_fraction / cross_section;
  const double bottom = hopper.funnel_top() + r_max;
  for (int i = 0; i < c.N; ++i) {
    Vec<D> p;
    if constexpr (D == 2) {
      // about the container's centre (0 unless a funnel wall is vertical: adding it changes no bit)
      p[0] = hopper.lateral_centre() + rng.uniform(-half, half);
    } else {
      double px, py;  // uniform in the disk by rejection: the count of draws is deterministic
      do {
        px = rng.uniform(-half, half);
        py = rng.uniform(-half, half);
      } while (px * px + py * py > half * half);
      p[0] = px;
      p[1] = py;
    }
    p[kUp<D>] = bottom + rng.uniform() * height;
    s.x[i] = p;
  }
}

template void place_randomly<2>(ParticleState<2>&, const SimConfig&, const Hopper<2>&, Rng&);
template void place_randomly<3>(ParticleState<3>&, const SimConfig&, const Hopper<3>&, Rng&);

}  // namespace beverloo
