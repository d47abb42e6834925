#pragma once
/// \file harmonic_overlap.h
/// \brief The one functional form of every repulsion in the models (SP pairs, walls, and later
/// DP contacts): U(d) = (eps/2) (1 - d/delta)^2 for d < delta, 0 otherwise.
namespace beverloo {

struct HarmonicOverlap {
  /// Energy at distance d for contact distance 1/inv_delta; writes dU/dd (<= 0) to dU_dd.
  static double energy(double eps, double d, double inv_delta, double& dU_dd) {
    const double overlap = 1.0 - d * inv_delta;
    dU_dd = -eps * overlap * inv_delta;
    return 0.5 * eps * overlap * overlap;
  }
  /// Stiffness d^2U/dd^2 = eps / delta^2: what limits the time step.
  static double stiffness(double eps, double delta) { return eps / (delta * delta); }
};

}  // namespace beverloo
