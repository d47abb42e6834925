// The draining hopper's fit dN/dt = -c0 sqrt(N) (engine/protocol/drain_fit): exact on the
// deterministic law, calibrated errors on a random death process, the steady part as defined.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/protocol/drain_fit.h"
#include "engine/rng.h"

namespace beverloo {
namespace {

/// Exit times of the deterministic law N(t) = (sqrt(N0) - c0 t / 2)^2: exit k leaves N0 - k - 1.
std::vector<double> exact_exits(int n0, double c0) {
  std::vector<double> t(n0);
  for (int k = 0; k < n0; ++k) t[k] = 2 * (std::sqrt(double(n0)) - std::sqrt(double(n0 - k - 1))) / c0;
  return t;
}

/// A death process with rate c0 sqrt(N): exponential waiting times (what the fit's errors assume).
std::vector<double> random_exits(int n0, double c0, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> t(n0);
  double now = 0;
  for (int k = 0; k < n0; ++k) {
    now += -std::log(1 - rng.uniform()) / (c0 * std::sqrt(double(n0 - k)));
    t[k] = now;
  }
  return t;
}

TEST(DrainFit, RecoversC0OfTheExactLaw) {
  const DrainFit f = fit_drain(exact_exits(1500, 0.8), 1500, 100, 10);
  ASSERT_TRUE(f.ok) << f.message;
  EXPECT_NEAR(f.c0, 0.8, 0.8 * 2e-3);
  EXPECT_EQ(f.exits_used, f.blocks * 10);
  // only exits with at least 100 left before them, after the first 100
  EXPECT_LE(f.exits_used, 1500 - 200);
  EXPECT_GT(f.t_last, f.t_first);
}

TEST(DrainFit, ErrorsAreCalibratedOnARandomDeathProcess) {
  const double c0 = 0.5;
  int within_2sigma = 0, runs = 200;
  double mean_pull = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    const DrainFit f = fit_drain(random_exits(600, c0, seed), 600, 100, 10);
    ASSERT_TRUE(f.ok) << f.message;
    const double pull = (f.c0 - c0) / f.c0_err;
    mean_pull += pull / runs;
    within_2sigma += std::fabs(pull) < 2;
  }
  // 95 % expected within 2 sigma (the chi2 scaling only widens); the mean pull near 0 (a bias of
  // the block rate m / duration is O(1/m), well below the error here)
  EXPECT_GE(within_2sigma, 0.88 * runs);
  EXPECT_LT(std::fabs(mean_pull), 0.35);
}

TEST(DrainFit, LeavesOutTheFirstAndLastExits) {
  // the first and the last 100 exits come far too fast or slow; the fit must not notice
  std::vector<double> t = exact_exits(800, 0.6);
  for (int k = 0; k < 100; ++k) t[k] *= 0.01;                                   // a burst at the start
  for (int k = 700; k < 800; ++k) t[k] = t[699] + 50.0 * (k - 699);             // a slow tail
  const DrainFit f = fit_drain(t, 800, 100, 10);
  ASSERT_TRUE(f.ok) << f.message;
  EXPECT_NEAR(f.c0, 0.6, 0.6 * 5e-3);
}

TEST(DrainFit, TooFewExitsIsNoFitAndSaysWhy) {
  const DrainFit f = fit_drain(exact_exits(200, 0.6), 200, 90, 10);
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.message.find("too few steady exits"), std::string::npos) << f.message;
  // a hopper that stopped early (fewer exits than particles): only the exits there are count
  const std::vector<double> t = exact_exits(1000, 0.6);
  const DrainFit part = fit_drain(std::vector<double>(t.begin(), t.begin() + 400), 1000, 100, 10);
  ASSERT_TRUE(part.ok) << part.message;
  EXPECT_NEAR(part.c0, 0.6, 0.6 * 2e-3);
  EXPECT_EQ(part.exits_used, 290);  // exits 100 .. 399 in blocks of 10 spanning 11 exits each
}

}  // namespace
}  // namespace beverloo
