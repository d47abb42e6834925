#pragma once
/// \file units.h
/// \brief The unit system, stated once. beverloo uses these units everywhere in the engine.
///
///   length        sigma_avg = (sigma_s + sigma_l) / 2          = 1
///   acceleration  g                                            = 1
///   mass density  rho (areal in 2D, volumetric in 3D)          = 1
///   time          t0 = sqrt(sigma_avg / g)                     = 1
///   flow rate     Q0 = sigma_avg^d / t0                        = 1
///   drag zeta, kinetic friction mu:  rho sigma_avg^(d-1) g t0  = 1
///   energies E_sp, E_w, E_c, K_*:    g rho sigma_avg^(d+1)     = 1
///
/// Masses follow from the density: M = rho * (pi sigma^2 / 4) in 2D, rho * (pi sigma^3 / 6) in 3D.
/// No force prefactor is rescaled anywhere; a number in a job file is a number in these units.
/// Angles are degrees at the JSON boundary and radians inside the engine.

#include <numbers>

namespace beverloo::units {
inline constexpr double g = 1.0;
inline constexpr double rho = 1.0;
inline constexpr double sigma_avg = 1.0;
inline constexpr double pi = std::numbers::pi;
inline constexpr double deg_to_rad(double deg) { return deg * pi / 180.0; }
}  // namespace beverloo::units
