// The Kaplan-Meier estimate of the time to a clog, against a hand-worked example and against
// the known answer for exponential clog times censored at t_max.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/rng.h"
#include "reports/survival.h"

namespace beverloo {
namespace {

TEST(KaplanMeier, HandWorkedExampleWithTiesAndCensoring) {
  // clogs at 2, 3, 3, 6; censored at 3 (still at risk at the tie), 4 and 8
  const KaplanMeier km = kaplan_meier({{6, true}, {3, true}, {4, false}, {2, true}, {8, false}, {3, false}, {3, true}});
  EXPECT_EQ(km.runs, 7);
  EXPECT_EQ(km.clogs, 4);
  ASSERT_EQ(km.time.size(), 3u);
  // t = 2: 7 at risk, 1 clog -> 6/7; t = 3: 6 at risk, 2 clogs -> 6/7 * 4/6; t = 6: 2 at risk -> x 1/2
  EXPECT_DOUBLE_EQ(km.survival[0], 6.0 / 7);
  EXPECT_DOUBLE_EQ(km.survival[1], 6.0 / 7 * 4.0 / 6);
  EXPECT_DOUBLE_EQ(km.survival[2], 6.0 / 7 * 4.0 / 6 * 0.5);
  const double g = 1.0 / (7 * 6) + 2.0 / (6 * 4) + 1.0 / (2 * 1);
  EXPECT_NEAR(km.survival_err[2], km.survival[2] * std::sqrt(g), 1e-15);
  EXPECT_DOUBLE_EQ(km.at(1.9), 1.0);
  EXPECT_DOUBLE_EQ(km.at(5), km.survival[1]);
  EXPECT_DOUBLE_EQ(km.median(), 6);  // S(3) = 4/7 > 1/2, S(6) = 2/7
  EXPECT_TRUE(std::isnan(kaplan_meier({{5, false}, {9, false}}).median()));
  EXPECT_EQ(kaplan_meier({}).at(10), 1.0);
}

TEST(KaplanMeier, RecoversExponentialSurvivalUnderCensoringWithCalibratedErrors) {
  // clog rate 1/50 per t0, runs censored at t_max = 40: S(30) = exp(-0.6)
  const double rate = 0.02, t_max = 40, t = 30, truth = std::exp(-rate * t);
  int covered = 0;
  const int trials = 400;
  for (int k = 0; k < trials; ++k) {
    Rng rng(900 + k);
    std::vector<SurvivalObservation> obs;
    for (int r = 0; r < 60; ++r) {
      const double clog = -std::log(1 - rng.uniform()) / rate;
      obs.push_back(clog < t_max ? SurvivalObservation{clog, true} : SurvivalObservation{t_max, false});
    }
    const KaplanMeier km = kaplan_meier(obs);
    covered += std::fabs(km.at(t) - truth) < km.err_at(t);
  }
  EXPECT_GT(covered, trials * 0.60);  // one Greenwood sigma: ~68 %
  EXPECT_LT(covered, trials * 0.76);
}

}  // namespace
}  // namespace beverloo
