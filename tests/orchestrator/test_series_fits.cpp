// One series' fits from its runs (reports/series_fits.h): the run-to-run spread of beta and of
// k over replicas, each replica fitted alone, in the free fit and in the authors' held fits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "reports/series_fits.h"

namespace beverloo {
namespace {

/// Replicas r = 0, 1, 2 of a drag-only 2D series whose flow follows Q = 5 (w - k_r)^(1/2)
/// exactly (1 % errors), k_r = 1.8, 2.0, 2.2: every fit of one replica recovers its k_r, so
/// each spread of k is the sample standard deviation of the three, 0.2, and beta's is 0.
std::vector<RunRecord> three_replicas(bool drop_a_width_of_the_last) {
  std::vector<RunRecord> runs;
  const double ks[] = {1.8, 2.0, 2.2};
  for (int r = 0; r < 3; ++r)
    for (double w = 4; w <= 10; w += 1) {
      if (drop_a_width_of_the_last && r == 2 && w == 7) continue;
      RunRecord run;
      run.w = w, run.replica = r;
      run.Q = 5 * std::sqrt(w - ks[r]);
      run.Q_err = 0.01 * run.Q;
      runs.push_back(run);
    }
  return runs;
}

Series drag_only_series() {
  Series s;
  s.dimension = 2, s.lambda = INFINITY, s.model = "dp_smooth";
  return s;
}

TEST(SeriesFits, TheSpreadOfKOverReplicasIsTheSampleDeviationOfEachReplicasOwnFit) {
  Series s = drag_only_series();
  fit_series(s, three_replicas(false));
  ASSERT_TRUE(s.fit);
  EXPECT_EQ(s.replica_fits, 3);
  EXPECT_NEAR(s.beta_replica_spread, 0, 1e-6);
  EXPECT_NEAR(s.k_replica_spread, 0.2, 1e-5);
  EXPECT_NEAR(s.k_at_beta_lo_replica_spread, 0.2, 1e-6);  // beta held at d - 3/2 = 1/2: exact
  ASSERT_TRUE(s.authors_fixed_lo);
  EXPECT_NEAR(s.authors_fixed_lo->k, 2.0, 0.02);          // the pooled points: between the three
  EXPECT_TRUE(std::isfinite(s.k_at_beta_hi_replica_spread));
}

TEST(SeriesFits, AReplicaWithoutEveryWidthIsLeftOutOfTheSpreads) {
  Series s = drag_only_series();
  fit_series(s, three_replicas(true));
  EXPECT_EQ(s.replica_fits, 2);
  EXPECT_NEAR(s.k_at_beta_lo_replica_spread, std::sqrt(0.02), 1e-6);  // 1.8 and 2.0 alone
  Series one = drag_only_series();
  std::vector<RunRecord> runs = three_replicas(false);
  runs.resize(7);  // replica 0 alone: no spread
  fit_series(one, runs);
  EXPECT_TRUE(std::isnan(one.k_replica_spread));
  EXPECT_TRUE(std::isnan(one.k_at_beta_lo_replica_spread));
}

}  // namespace
}  // namespace beverloo
