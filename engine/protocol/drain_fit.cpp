#include "drain_fit.h"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>

namespace beverloo {

DrainFit fit_drain(const std::vector<double>& exit_times, int n_initial, int skip, int block_exits) {
  DrainFit fit;
  const int exits = static_cast<int>(exit_times.size());
  // exit k (0-based) leaves n_initial - k - 1 behind; it is steady if k >= skip and it was made
  // with at least `skip` left before it (n_initial - k > skip)
  const int first = skip, end = std::min(exits, n_initial - skip);
  const int usable = end - first;
  if (usable < 3 * block_exits + 1) {
    fit.message = "too few steady exits to fit dN/dt = -c0 sqrt(N): " + std::to_string(std::max(usable, 0)) +
                  " between the first " + std::to_string(skip) + " and the last " + std::to_string(skip) +
                  " (of " + std::to_string(exits) + " exits, " + std::to_string(n_initial) +
                  " particles at the start); a fit needs 3 blocks of " + std::to_string(block_exits);
    return fit;
  }
  // Block b: the m intervals between exits k0 .. k0 + m. The interval after exit k passes with
  // N = n_initial - k - 1 in the hopper; with exit rate c0 sqrt(N) its mean length is
  // 1/(c0 sqrt(N)) and its variance 1/(c0^2 N). So the block's duration tau_b has mean S_b / c0
  // and variance V_b / c0^2 with S_b = sum 1/sqrt(N), V_b = sum 1/N: a straight line through the
  // origin, tau = a S with a = 1/c0, fitted with weights 1/V_b. (Fitting the rates m / tau
  // instead is biased: the mean of m / tau is m/(m-1) times the rate, and weights taken from
  // the data favour the slow blocks.)
  std::vector<double> S, V, tau;
  for (int k0 = first; k0 + block_exits < end; k0 += block_exits) {
    double s_b = 0, v_b = 0, n_sum = 0;
    for (int k = k0; k < k0 + block_exits; ++k) {
      const double n = double(n_initial) - k - 1;
      s_b += 1 / std::sqrt(n);
      v_b += 1 / n;
      n_sum += n;
    }
    const double duration = exit_times[k0 + block_exits] - exit_times[k0];
    S.push_back(s_b);
    V.push_back(v_b);
    tau.push_back(duration);
    // for figures: the block's mean N and its mean rate (with the error of m waiting times)
    const double rate = duration > 0 ? block_exits / duration : 0;
    fit.block_N.push_back(n_sum / block_exits);
    fit.block_rate.push_back(rate);
    fit.block_rate_err.push_back(rate / std::sqrt(double(block_exits)));
    if (fit.blocks == 0) fit.t_first = exit_times[k0];
    fit.t_last = exit_times[k0 + block_exits];
    ++fit.blocks;
    fit.exits_used += block_exits;
  }
  if (fit.blocks < 3) {
    fit.message = "fewer than 3 rate blocks";
    return fit;
  }
  std::vector<double> w(fit.blocks);
  for (int b = 0; b < fit.blocks; ++b) w[b] = 1.0 / V[b];
  double a = 0, cov_unit = 0, sumsq = 0;
  gsl_fit_wmul(S.data(), 1, w.data(), 1, tau.data(), 1, fit.blocks, &a, &cov_unit, &sumsq);
  // the variances are V / c0^2 = V a^2: the covariance and chi2 of weights 1/V scale by a^2
  const double var_a = cov_unit * a * a;
  fit.chi2_red = sumsq / (a * a) / (fit.blocks - 1);
  const double a_err = std::sqrt(var_a) * std::max(1.0, std::sqrt(fit.chi2_red));
  fit.c0 = 1 / a;
  fit.c0_err = a_err / (a * a);
  fit.ok = std::isfinite(fit.c0) && std::isfinite(fit.c0_err) && a > 0;
  if (!fit.ok) fit.message = "the fit of dN/dt = -c0 sqrt(N) gave no positive, finite c0";
  return fit;
}

}  // namespace beverloo
