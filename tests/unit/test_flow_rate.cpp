// The steady-state flow rate estimator on synthetic exit series with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/protocol/flow_rate.h"
#include "engine/rng.h"

namespace beverloo {
namespace {

/// Poisson exits of unit size at `rate` per t0 after t_on, with a slower start before.
FlowRecord synthetic_exits(double rate, double t_on, double t_end, std::uint64_t seed, double early_rate = 0) {
  FlowRecord rec;
  Rng rng(seed);
  double t = 0;
  while (true) {
    const double r = t < t_on ? early_rate : rate;
    if (r <= 0) {
      t = t_on;
      continue;
    }
    t += -std::log(1 - rng.uniform()) / r;
    if (t >= t_end) break;
    rec.exit_time.push_back(t);
    rec.exit_size.push_back(1.0);
    rec.exit_particle.push_back(0);
  }
  return rec;
}

TEST(FlowRate, Mser5FindsTheEndOfAStartUp) {
  std::vector<double> series(400, 10.0);
  Rng rng(3);
  for (auto& x : series) x += rng.uniform(-1, 1);
  for (int k = 0; k < 60; ++k) series[k] = 0.1 * k;  // ramp over 60 bins
  const int cut = FlowRateEstimator::mser5_truncation(series);
  EXPECT_GE(cut, 50);
  EXPECT_LE(cut, 80);
}

TEST(FlowRate, BlockingErrorOfIndependentDataIsTheNaiveError) {
  Rng rng(4);
  std::vector<double> x(4096);
  for (auto& v : x) v = rng.uniform(-1, 1);  // variance 1/3
  const double se = FlowRateEstimator::blocking_standard_error(x);
  const double naive = std::sqrt(1.0 / 3.0 / 4096);
  EXPECT_GT(se, 0.85 * naive);
  EXPECT_LT(se, 1.6 * naive);  // the max over levels is conservative, not wild
}

TEST(FlowRate, BlockingSeesCorrelations) {
  Rng rng(5);
  std::vector<double> x(4096);
  double ar = 0;
  for (auto& v : x) v = ar = 0.9 * ar + rng.uniform(-1, 1);  // AR(1), tau ~ 10
  const double naive = FlowRateEstimator::blocking_standard_error(x, 4096);  // level 0 only
  const double blocked = FlowRateEstimator::blocking_standard_error(x);
  EXPECT_GT(blocked, 3 * naive);  // sqrt((1 + 0.9)/(1 - 0.9)) = 4.4
}

TEST(FlowRate, RecoversPoissonRateWithCalibratedError) {
  RunControls rc;
  rc.min_transient = 20;
  int inside = 0;
  const int trials = 60;
  std::vector<double> cuts;
  for (int k = 0; k < trials; ++k) {
    FlowRecord rec = synthetic_exits(5.0, 30, 430, 100 + k, 0.5);
    FlowRateEstimator est(rc);
    const FlowRateEstimate e = est.estimate(rec, 430);
    ASSERT_TRUE(e.valid);
    EXPECT_GE(e.t_start, 25);  // the slow start is always cut ...
    cuts.push_back(e.t_start);
    if (std::fabs(e.Q - 5.0) < e.Q_err) ++inside;
  }
  // ... and typically not much more (MSER may cut extra on a noisy stretch: data lost, no bias)
  std::sort(cuts.begin(), cuts.end());
  EXPECT_LE(cuts[trials / 2], 60);
  // one-sigma coverage ~68%; the conservative blocking estimate may cover a little more
  EXPECT_GE(inside, trials * 0.55);
  EXPECT_LE(inside, trials * 0.92);
}

}  // namespace
}  // namespace beverloo
