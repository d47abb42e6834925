#pragma once
/// \file hertz_normal.h
/// \brief The Hertzian normal force, the repulsion DEM users expect between elastic spheres
/// (sp_contact_law "hertz"; not in the paper): for a pair of contact distance sigma at distance
/// r < sigma, with the overlap ov = 1 - r/sigma,
///   U = (2/5) eps ov^(5/2),   |F| = -dU/dr = eps ov^(3/2) / sigma,
/// eps = E_sp, the pair's energy scale as in the "energy" law (so E_sp keeps its meaning and
/// its units). A material's Hertz force (4/3) E* sqrt(R*) delta^(3/2), delta = sigma ov, is
/// this with eps = (4/3) E* sqrt(R*) sigma^(5/2) for that pair.
///
/// In 2D: two parallel cylinders (discs) pressed together along a line have no power law of
/// the overlap (linear up to a logarithm; Johnson, Contact Mechanics, sec. 4.3), so there is
/// no exact 2D Hertz. beverloo applies ov^(3/2) in 2D too, as 2D DEM codes commonly do (the
/// 3D sphere law on discs); the harmonic "energy" law is the linear 2D alternative.
///
/// The stiffness d^2U/dr^2 = (3/2) eps ov^(1/2) / sigma^2 grows with the overlap; dt "auto"
/// takes its largest value over 0 < ov < 1, (3/2) eps / sigma^2 (a run with ov near 1 has
/// blown up anyway), so the step resolves every contact this law can hold.
#include <cmath>

namespace beverloo {

struct HertzNormal {
  static constexpr bool kLanes = false;  ///< runs at scalar width (contact_laws.h)
  [[gnu::always_inline]] static inline double force(double eps, double inv_sig, double r, double& energy, double& ov) {
    ov = 1.0 - r * inv_sig;
    const double ov_root = std::sqrt(ov);
    energy += 0.4 * eps * ov * ov * ov_root;
    return eps * ov * ov_root * inv_sig;
  }
  static double stiffness(double eps, double sigma) { return 1.5 * eps / (sigma * sigma); }
};

}  // namespace beverloo
