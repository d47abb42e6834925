#include "state.h"

#include "units.h"

namespace beverloo {

Species Species::bidisperse(int dimension, double size_ratio) {
  Species s;
  // sigma_avg = (sigma_s + sigma_l) / 2 = 1 defines the length unit.
  s.sigma[0] = 2.0 / (1.0 + size_ratio);
  s.sigma[1] = size_ratio * s.sigma[0];
  for (int k = 0; k < 2; ++k) {
    const double d = s.sigma[k];
    s.ref_size[k] = dimension == 2 ? units::pi * d * d / 4 : units::pi * d * d * d / 6;
    s.mass[k] = units::rho * s.ref_size[k];
  }
  return s;
}

}  // namespace beverloo
