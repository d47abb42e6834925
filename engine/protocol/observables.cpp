#include "observables.h"

#include <cmath>

#include "../units.h"
#include "flow_rate.h"

namespace beverloo {

template <int D>
FlowObservables<D>::FlowObservables(const SimConfig& c)
    : block_length_(c.observables.block_length), dh_(c.observables.profile_dh), width_(c.observables.kernel_width),
      w_(c.w), nh_(static_cast<int>(std::floor(c.observables.profile_h_max / c.observables.profile_dh)) + 1) {
  const int expected = static_cast<int>(std::min(4096.0, c.run.t_max / block_length_ + 2));
  block_scalars.reserve(expected * kScalars);
  block_profile.reserve(static_cast<std::size_t>(expected) * nh_);
}

template <int D>
void FlowObservables<D>::ensure_block(int b) {
  if (static_cast<int>(block_scalars.size()) < (b + 1) * kScalars) {
    block_scalars.resize((b + 1) * kScalars, 0.0);
    block_profile.resize(static_cast<std::size_t>(b + 1) * nh_, 0.0);
  }
}

template <int D>
void FlowObservables<D>::sample(const ParticleState<D>& s, double t, const VecArray<D>& friction,
                                const std::array<double, 2>& drag_coefficient) {
  const int b = static_cast<int>(std::floor(t / block_length_));
  ensure_block(b);
  double* sc = &block_scalars[b * kScalars];
  double* prof = &block_profile[static_cast<std::size_t>(b) * nh_];
  const double cut = 3 * width_, inv2s2 = 1.0 / (2 * width_ * width_);
  const double norm = std::pow(std::sqrt(2 * units::pi) * width_, -D);
  double count = 0, drag = 0, fric = 0;
  const int n = s.size();
  for (int i = 0; i < n; ++i) {
    const double h = s.x[i][kUp<D>], lat = Hopper<D>::lateral(s.x[i]);
    if (h > 0 && h < w_ && lat < w_) count += 1;
    drag += drag_coefficient[s.species[i]] * s.v[i].norm();
    fric += friction[i].norm();
    if (lat >= cut) continue;
    const double vg = -s.v[i][kUp<D>];
    const int k_lo = std::max(0, static_cast<int>(std::ceil((h - cut) / dh_)));
    const int k_hi = std::min(nh_ - 1, static_cast<int>(std::floor((h + cut) / dh_)));
    for (int k = k_lo; k <= k_hi; ++k) {
      const double dz = k * dh_ - h;
      const double r2 = lat * lat + dz * dz;
      if (r2 < cut * cut) prof[k] += vg * norm * std::exp(-r2 * inv2s2);
    }
  }
  const double volume = D == 2 ? 2 * w_ * w_ : units::pi * w_ * w_ * w_;
  sc[0] += 1;
  sc[1] += count / volume;
  sc[2] += drag / n;
  sc[3] += fric / n;
}

template <int D>
ObservableSummary FlowObservables<D>::summarize(double t_start) const {
  ObservableSummary out;
  const int nblocks = static_cast<int>(block_scalars.size()) / kScalars;
  const int first = first_block_at(t_start);
  out.h.resize(nh_);
  for (int k = 0; k < nh_; ++k) out.h[k] = k * dh_;
  std::vector<double> sum(nh_, 0), sum2(nh_, 0);
  double samples = 0, rho = 0, rho_b2 = 0, drag = 0, fric = 0;
  int used = 0;
  for (int b = first; b < nblocks; ++b) {
    const double* sc = &block_scalars[b * kScalars];
    if (sc[0] == 0) continue;
    ++used;
    samples += sc[0];
    rho += sc[1];
    rho_b2 += (sc[1] / sc[0]) * (sc[1] / sc[0]);
    drag += sc[2];
    fric += sc[3];
    for (int k = 0; k < nh_; ++k) {
      const double m = block_profile[static_cast<std::size_t>(b) * nh_ + k] / sc[0];
      sum[k] += m;
      sum2[k] += m * m;
    }
  }
  out.blocks_used = used;
  out.v_g.assign(nh_, 0);
  out.v_g_err.assign(nh_, 0);
  if (used == 0) return out;
  for (int k = 0; k < nh_; ++k) {
    const double mean = sum[k] / used;
    out.v_g[k] = mean;
    if (used > 1) out.v_g_err[k] = std::sqrt(std::max(0.0, sum2[k] / used - mean * mean) / (used - 1));
  }
  out.rho_n = rho / samples;
  if (used > 1) {
    // blocks hold equal numbers of samples except possibly the last: use block means
    double mean_b = 0;
    for (int b = first; b < nblocks; ++b)
      if (block_scalars[b * kScalars] > 0) mean_b += block_scalars[b * kScalars + 1] / block_scalars[b * kScalars];
    mean_b /= used;
    out.rho_n_err = std::sqrt(std::max(0.0, rho_b2 / used - mean_b * mean_b) / (used - 1));
  }
  out.mean_F_drag = drag / samples;
  out.mean_F_friction = fric / samples;
  out.force_ratio = out.mean_F_friction > 0 ? out.mean_F_drag / out.mean_F_friction : INFINITY;
  out.force_ratio_err = force_ratio_error(first, out.force_ratio, out.mean_F_friction);
  return out;
}

template <int D>
double FlowObservables<D>::force_ratio_error(int first_block, double ratio, double mean_friction) const {
  // R = <d> / <f> over the window. To first order its fluctuation is (d - R f) / <f>, so the
  // error of R is that of the mean of u_b = (d_b - R f_b) / <f> over the blocks' means: a
  // sum of correlated samples, blocked in pairs until few blocks are left (the force
  // magnitudes follow the flow's slow pulses, longer than one 5 t0 block at times).
  if (!(mean_friction > 0) || !std::isfinite(ratio)) return NAN;
  std::vector<double> u;
  const int nblocks = static_cast<int>(block_scalars.size()) / kScalars;
  for (int b = first_block; b < nblocks; ++b) {
    const double* sc = &block_scalars[b * kScalars];
    if (sc[0] == 0) continue;
    u.push_back((sc[2] / sc[0] - ratio * sc[3] / sc[0]) / mean_friction);
  }
  if (u.size() < 2) return NAN;
  return FlowRateEstimator::blocking_standard_error(u);
}

template class FlowObservables<2>;
template class FlowObservables<3>;

}  // namespace beverloo
