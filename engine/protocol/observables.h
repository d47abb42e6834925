#pragma once
/// \file observables.h
/// \brief Sampled observables of physics.md 7, accumulated in time blocks so that the start-up
/// transient found from the exits can be dropped afterwards and errors come from block scatter:
///  - v_g(h): Gaussian coarse-grained (width kernel_width, cut at 3 widths) velocity along
///    gravity (positive downward) on the centre line, v_g(r) = sum_i v_g,i phi(r - r_i) with
///    phi = (sqrt(2 pi) s)^-d exp(-|r|^2 / 2 s^2);
///  - rho_n: number density in the rectangle 2w wide and w tall above the orifice (3D: the
///    cylinder of diameter 2w and height w);
///  - mean |F^zeta| and |F^mu| per particle (all N particles), and their ratio with its
///    standard error (the ratio of the window's means; its error by the delta method over the
///    blocks, blocked further in pairs as the flow rate's, FlowRateEstimator).
#include <cmath>
#include <cstdint>
#include <vector>

#include "../config.h"
#include "../geometry/hopper.h"
#include "../state.h"

namespace beverloo {

struct ObservableSummary {
  std::vector<double> h, v_g, v_g_err;  ///< profile heights and values (err: SE over blocks)
  double rho_n = 0, rho_n_err = 0;
  double mean_F_drag = 0, mean_F_friction = 0;
  /// mean_F_drag / mean_F_friction (inf without friction) and its standard error (NaN without
  /// friction or with fewer than two blocks)
  double force_ratio = 0, force_ratio_err = NAN;
  int blocks_used = 0;
};

template <int D>
class FlowObservables {
 public:
  FlowObservables(const SimConfig& c);
  /// One sample at time t; friction holds the friction force of each particle.
  /// drag_coefficient: per species, of a particle (DP: of a whole polygon)
  void sample(const ParticleState<D>& s, double t, const VecArray<D>& friction, const std::array<double, 2>& drag_coefficient);
  /// Averages over the blocks that start at or after t_start.
  ObservableSummary summarize(double t_start) const;

  // Raw block data (for checkpoints).
  int heights() const { return nh_; }
  std::vector<double> block_scalars;  ///< per block: samples, density count, sum|F_drag|, sum|F_fric|
  std::vector<double> block_profile;  ///< per block: nh sums of v_g
  static constexpr int kScalars = 4;

 private:
  void ensure_block(int b);
  int first_block_at(double t_start) const { return static_cast<int>(std::ceil(t_start / block_length_ - 1e-9)); }
  double force_ratio_error(int first_block, double ratio, double mean_friction) const;
  double block_length_, dh_, width_, w_;
  int nh_;
};

}  // namespace beverloo
