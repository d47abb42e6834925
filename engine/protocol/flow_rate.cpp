#include "flow_rate.h"

#include <algorithm>
#include <cmath>

namespace beverloo {

int FlowRateEstimator::mser5_truncation(const std::vector<double>& series) {
  const int batch = 5;
  const int m = static_cast<int>(series.size()) / batch;
  if (m < 2) return 0;
  std::vector<double> y(m);
  for (int k = 0; k < m; ++k) {
    double s = 0;
    for (int b = 0; b < batch; ++b) s += series[k * batch + b];
    y[k] = s / batch;
  }
  // suffix sums give mean and variance of y[d..m) in O(m)
  std::vector<double> s1(m + 1, 0), s2(m + 1, 0);
  for (int k = m - 1; k >= 0; --k) {
    s1[k] = s1[k + 1] + y[k];
    s2[k] = s2[k + 1] + y[k] * y[k];
  }
  int best = 0;
  double best_value = INFINITY;
  for (int d = 0; d <= m / 2; ++d) {
    const double cnt = m - d;
    const double mean = s1[d] / cnt;
    const double ss = std::max(0.0, s2[d] - cnt * mean * mean);
    const double value = ss / (cnt * cnt);
    if (value < best_value) {
      best_value = value;
      best = d;
    }
  }
  return best * batch;
}

double FlowRateEstimator::blocking_standard_error(const std::vector<double>& series, int min_blocks) {
  std::vector<double> x = series;
  double best = 0;
  bool any = false;
  while (static_cast<int>(x.size()) >= std::max(2, min_blocks) || !any) {
    const int n = static_cast<int>(x.size());
    if (n < 2) break;
    double mean = 0;
    for (double v : x) mean += v;
    mean /= n;
    double var = 0;
    for (double v : x) var += (v - mean) * (v - mean);
    const double se = std::sqrt(var / (static_cast<double>(n) * (n - 1)));
    best = std::max(best, se);
    any = true;
    for (int k = 0; k < n / 2; ++k) x[k] = 0.5 * (x[2 * k] + x[2 * k + 1]);
    x.resize(n / 2);
  }
  return best;
}

FlowRateEstimate FlowRateEstimator::estimate(const FlowRecord& rec, double t_now) {
  FlowRateEstimate e;
  const double bin = rc_.rate_bin;
  const int nbins = static_cast<int>(std::floor(t_now / bin + 1e-9));
  rate_.assign(std::max(nbins, 0), 0.0);
  for (std::size_t k = 0; k < rec.exit_time.size(); ++k) {
    const int b = static_cast<int>(rec.exit_time[k] / bin);
    if (b < nbins) rate_[b] += rec.exit_size[k] / bin;
  }
  const int min_cut = static_cast<int>(std::ceil(rc_.min_transient / bin - 1e-9));
  const int cut = std::max(min_cut, mser5_truncation(rate_));
  e.t_start = cut * bin;
  e.t_end = nbins * bin;
  e.bins = nbins - cut;
  if (e.bins < 2) return e;
  double sum = 0;
  for (int b = cut; b < nbins; ++b) sum += rate_[b];
  e.Q = sum / e.bins;
  for (double t : rec.exit_time)
    if (t >= e.t_start && t < e.t_end) ++e.exits_in_window;
  const std::vector<double> window(rate_.begin() + cut, rate_.begin() + nbins);
  e.Q_err = blocking_standard_error(window);
  e.valid = e.bins >= 16;
  return e;
}

}  // namespace beverloo
