#pragma once
/// \file fire.h
/// \brief FIRE energy minimisation (Bitzek et al., PRL 97, 170201, 2006) on any force field.
/// The caller chooses what is minimised (the hopper protocol switches gravity and dissipation
/// off to remove overlaps).
#include <cstdint>

#include "../config.h"
#include "../forces/force_field.h"

namespace beverloo {

struct FireResult {
  bool converged = false;
  std::int64_t iterations = 0;
  double max_force = 0;  ///< largest |F_i| at the end
  double energy = 0;     ///< potential energy at the end
};

template <int D>
FireResult fire_minimize(ParticleState<D>& s, ForceField<D>& ff, const FireParams& p, double dt0);

}  // namespace beverloo
