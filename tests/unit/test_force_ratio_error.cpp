// The force ratio |F_zeta| / |F_mu| of a run and its standard error (FlowObservables): on
// synthetic block sums with a known ratio, the quoted error must match the scatter of the
// ratio over many independent windows, also when neighbouring blocks are correlated.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/config.h"
#include "engine/protocol/observables.h"
#include "engine/rng.h"

namespace beverloo {
namespace {

constexpr double kRatio = 0.04;          // the true <|F_drag|> / <|F_friction|>
constexpr double kMeanFriction = 0.7;    // rho sigma_avg^2 g, per particle
constexpr int kSamplesPerBlock = 50;

double normal(Rng& rng) {  // Box-Muller
  return std::sqrt(-2 * std::log(1 - rng.uniform())) * std::cos(2 * 3.141592653589793 * rng.uniform());
}

SimConfig observed_hopper() {
  SimConfig c;
  c.dimension = 2;
  c.w = 6;
  c.run.t_max = 2000;
  return c;
}

/// Fills the blocks of `obs` from block 0 on with per-block mean forces: friction and drag
/// each fluctuate about their means by AR(1) noise from block to block (phi: the
/// correlation of neighbouring blocks), drag partly following friction as in a flow pulse.
void fill_blocks(FlowObservables<2>& obs, int blocks, double phi, Rng& rng) {
  obs.block_scalars.assign(static_cast<std::size_t>(blocks) * FlowObservables<2>::kScalars, 0.0);
  obs.block_profile.assign(static_cast<std::size_t>(blocks) * obs.heights(), 0.0);
  const double innovation = std::sqrt(1 - phi * phi);
  double xf = normal(rng), xd = normal(rng);
  for (int b = 0; b < blocks; ++b) {
    xf = phi * xf + innovation * normal(rng);
    xd = phi * xd + innovation * normal(rng);
    const double friction = kMeanFriction * (1 + 0.10 * xf);
    const double drag = kRatio * kMeanFriction * (1 + 0.06 * xf + 0.08 * xd);
    double* sc = &obs.block_scalars[static_cast<std::size_t>(b) * FlowObservables<2>::kScalars];
    sc[0] = kSamplesPerBlock;
    sc[1] = kSamplesPerBlock * 0.8;
    sc[2] = kSamplesPerBlock * drag;
    sc[3] = kSamplesPerBlock * friction;
  }
}

struct Scatter {
  double mean_ratio, sd_ratio, mean_err;
};

Scatter windows(double phi, int blocks, int realizations) {
  const SimConfig c = observed_hopper();
  FlowObservables<2> obs(c);
  Rng rng(11);
  double s = 0, s2 = 0, e = 0;
  for (int k = 0; k < realizations; ++k) {
    fill_blocks(obs, blocks, phi, rng);
    const ObservableSummary o = obs.summarize(0);
    s += o.force_ratio;
    s2 += o.force_ratio * o.force_ratio;
    e += o.force_ratio_err;
  }
  const double mean = s / realizations;
  return {mean, std::sqrt((s2 / realizations - mean * mean) * realizations / (realizations - 1)), e / realizations};
}

TEST(ForceRatioError, MatchesTheScatterOfIndependentWindows) {
  const Scatter w = windows(0.0, 64, 2000);
  // unbiased to second order (R var(f) / f^2 ~ 2.5e-6 here): within 4 standard errors of the
  // mean over the windows
  EXPECT_NEAR(w.mean_ratio, kRatio, 4 * w.sd_ratio / std::sqrt(2000.0));
  // the quoted error is that scatter (blocking over uncorrelated blocks changes little)
  EXPECT_GT(w.mean_err / w.sd_ratio, 0.85) << w.mean_err << " vs " << w.sd_ratio;
  EXPECT_LT(w.mean_err / w.sd_ratio, 1.2) << w.mean_err << " vs " << w.sd_ratio;
}

TEST(ForceRatioError, CountsCorrelationsBetweenBlocks) {
  // phi = 0.8 between 5 t0 blocks: the naive standard error over blocks is three times too
  // small; the pairwise blocking must find most of the true scatter
  const Scatter w = windows(0.8, 256, 1000);
  EXPECT_GT(w.mean_err / w.sd_ratio, 0.75) << w.mean_err << " vs " << w.sd_ratio;
  EXPECT_LT(w.mean_err / w.sd_ratio, 1.2) << w.mean_err << " vs " << w.sd_ratio;
}

TEST(ForceRatioError, OnlyTheWindowCounts) {
  const SimConfig c = observed_hopper();
  FlowObservables<2> obs(c);
  Rng rng(5);
  fill_blocks(obs, 40, 0.0, rng);
  // a start-up with ten times the drag in the first 8 blocks (40 t0): outside the window
  for (int b = 0; b < 8; ++b) obs.block_scalars[b * FlowObservables<2>::kScalars + 2] *= 10;
  const ObservableSummary inside = obs.summarize(40.0);
  const ObservableSummary all = obs.summarize(0.0);
  EXPECT_NEAR(inside.force_ratio, kRatio, 5 * inside.force_ratio_err);
  EXPECT_GT(all.force_ratio, 2 * kRatio);
  EXPECT_LT(inside.force_ratio_err, 0.2 * all.force_ratio_err);
}

TEST(ForceRatioError, NoFrictionOrOneBlockHasNoError) {
  const SimConfig c = observed_hopper();
  FlowObservables<2> obs(c);
  Rng rng(7);
  fill_blocks(obs, 10, 0.0, rng);
  for (int b = 0; b < 10; ++b) obs.block_scalars[b * FlowObservables<2>::kScalars + 3] = 0;
  const ObservableSummary frictionless = obs.summarize(0);
  EXPECT_TRUE(std::isinf(frictionless.force_ratio));
  EXPECT_TRUE(std::isnan(frictionless.force_ratio_err));

  fill_blocks(obs, 10, 0.0, rng);
  const ObservableSummary last_block = obs.summarize(45.0);  // block 9 alone
  EXPECT_GT(last_block.force_ratio, 0);
  EXPECT_TRUE(std::isnan(last_block.force_ratio_err));

  // drag only through friction's pulses is still a ratio with an error; no drag: exactly 0 +- 0
  fill_blocks(obs, 10, 0.0, rng);
  for (int b = 0; b < 10; ++b) obs.block_scalars[b * FlowObservables<2>::kScalars + 2] = 0;
  const ObservableSummary dragless = obs.summarize(0);
  EXPECT_EQ(dragless.force_ratio, 0);
  EXPECT_EQ(dragless.force_ratio_err, 0);
}

}  // namespace
}  // namespace beverloo
