#pragma once
/// \file kinetic_friction.h
/// \brief Kinetic friction between overlapping particles (physics.md 3):
/// F_m = -mu * sum over n overlapping m of (v_m - v_n), on the full relative velocity vector,
/// pairwise equal and opposite (so momentum is conserved) and with power
/// -mu |v_m - v_n|^2 <= 0 per pair (so it only removes energy).
#include "../vec.h"

namespace beverloo {

template <int D>
inline Vec<D> kinetic_friction_force(double mu, const Vec<D>& v_m, const Vec<D>& v_n) {
  return -mu * (v_m - v_n);
}

}  // namespace beverloo
