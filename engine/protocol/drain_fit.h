#pragma once
/// \file drain_fit.h
/// \brief The draining hopper's law (physics.md 9): dN/dt = -c0 sqrt(N), with N the particles
/// (droplets) still in the hopper. Fitted on the steady part of a list of exit times: the first
/// `skip` exits and those made with fewer than `skip` left are not used (the transients of the
/// first and last ~100 droplets). The exits in between are cut into blocks of `block_exits`
/// consecutive exits. With N in the hopper the next exit comes after a mean 1/(c0 sqrt(N)) with
/// variance 1/(c0^2 N) (a death process), so a block's duration is S/c0 on average, with S the
/// sum of 1/sqrt(N) over its intervals: c0 is the inverse slope of durations against S, a
/// weighted least-squares line through the origin (GSL's gsl_fit_wmul, weights 1/sum(1/N)),
/// its error from that fit, scaled by sqrt(chi2_red) when that exceeds 1 (tests/unit/
/// test_drain_fit.cpp checks the errors on random death processes). Units are those of the
/// times given: t0 for simulations, seconds for measurements.
/// Used by the engine for its draining runs and by `beverloo experiment import` for measured
/// droplet exits, so that both are fitted the same way.
#include <string>
#include <vector>

namespace beverloo {

struct DrainFit {
  bool ok = false;
  std::string message;     ///< why there is no fit (too few exits), empty when ok
  double c0 = 0, c0_err = 0;
  double chi2_red = 0;
  int blocks = 0;          ///< rate blocks used
  int exits_used = 0;      ///< exits inside those blocks
  double t_first = 0, t_last = 0;  ///< time span of the blocks
  /// per block, for figures: mean N, mean rate (exits / duration) and its error
  std::vector<double> block_N, block_rate, block_rate_err;
};

/// exit_times: sorted, one per particle that left; n_initial: particles in the hopper at t = 0
/// (at least as many as the exits).
DrainFit fit_drain(const std::vector<double>& exit_times, int n_initial, int skip, int block_exits);


}  // namespace beverloo
