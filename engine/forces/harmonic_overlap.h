#pragma once
/// \file harmonic_overlap.h
/// \brief The harmonic repulsion of the paper, U(d) = (eps/2) (1 - d/delta)^2 for d < delta, 0
/// otherwise: the walls', the DP contacts', and the normal law of the SP pairs' "energy" and
/// "force" rows (contact_laws.h; the two differ in the pair's energy scale eps only).
namespace beverloo {

struct HarmonicOverlap {
  /// The pair runs have its SIMD lane form (sp_pairs_sse2.h, sp_pairs_avx2.h).
  static constexpr bool kLanes = true;
  /// A touching pair (r < sigma = 1/inv_sig): ov = 1 - r/sigma, U = (eps/2) ov^2 added to
  /// energy, returns |F| = -dU/dr = eps ov / sigma. The operations and their order are those
  /// of the lane forms and of energy() below: every width and every caller gives the same bits.
  [[gnu::always_inline]] static inline double force(double eps, double inv_sig, double r, double& energy, double& ov) {
    ov = 1.0 - r * inv_sig;
    energy += 0.5 * eps * ov * ov;
    return eps * ov * inv_sig;
  }
  /// Energy at distance d for contact distance 1/inv_delta; writes dU/dd (<= 0) to dU_dd.
  static double energy(double eps, double d, double inv_delta, double& dU_dd) {
    const double overlap = 1.0 - d * inv_delta;
    dU_dd = -eps * overlap * inv_delta;
    return 0.5 * eps * overlap * overlap;
  }
  /// Stiffness d^2U/dd^2 = eps / delta^2 (the same at every overlap): what limits the time step.
  static double stiffness(double eps, double delta) { return eps / (delta * delta); }
};

}  // namespace beverloo
