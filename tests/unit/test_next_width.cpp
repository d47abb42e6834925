// The design criterion for the next run of a Beverloo series (reports/next_width.h).
#include <gtest/gtest.h>

#include <cmath>

#include "reports/fit.h"
#include "reports/next_width.h"

namespace beverloo {
namespace {

struct Series {
  std::vector<double> w, Q, Q_err;
};

/// Exact Q = C (w - k)^beta with 2 % errors at the given widths.
Series exact(const std::vector<double>& widths, double C = 0.6, double k = 1.5, double beta = 1.5) {
  Series s;
  for (double w : widths) {
    s.w.push_back(w);
    s.Q.push_back(C * std::pow(w - k, beta));
    s.Q_err.push_back(0.02 * s.Q.back());
  }
  return s;
}

TEST(NextWidth, ItsErrorsAreTheFitsAndTheNextRunLowersThem) {
  const Series s = exact({6, 7, 8, 9, 10});
  const BeverlooFit f = fit_beverloo(s.w, s.Q, s.Q_err);
  const DesignAdvice a = next_width(f, s.w, s.Q, s.Q_err, 2.0, 10.0, 0.25);
  EXPECT_NEAR(a.k_err_now, f.k_err, 1e-3 * f.k_err);  // the fit's covariance, from the same information
  EXPECT_NEAR(a.beta_err_now, f.beta_err, 1e-3 * f.beta_err);
  ASSERT_TRUE(a.next.has_value());
  EXPECT_LT(a.next->k_err_after, a.k_err_now);
  EXPECT_LT(a.next->beta_err_after, a.beta_err_now);
  // on the grid, above k
  EXPECT_NEAR(std::fmod(a.next->w - 2.0, 0.25), 0.0, 1e-12);
  EXPECT_GT(a.next->w, f.k + 0.25);
  // within the range already run, the points leave k and beta loose at its low end: the best
  // next run lies below it (informative, and not yet as slow as near k)
  EXPECT_LT(a.next->w, 6.0);
  EXPECT_GT(a.next->w, 3.0);
  const DesignAdvice again = next_width(f, s.w, s.Q, s.Q_err, 2.0, 10.0, 0.25);
  EXPECT_EQ(again.next->w, a.next->w);  // deterministic
  // allowed beyond it, a wide width is cheaper per information (a fast flow, a longer lever arm
  // for beta): the range a user allows decides, as it should
  const DesignAdvice wide = next_width(f, s.w, s.Q, s.Q_err, 2.0, 20.0, 0.25);
  EXPECT_GT(wide.next->w, 10.0);
  EXPECT_LT(wide.next->relative_cost, a.next->relative_cost);
}

TEST(NextWidth, ASeriesSpreadAcrossTheRangeAsksForLessThanOneBunchedFar) {
  const Series far = exact({8, 8.5, 9, 9.5, 10}), spread = exact({3, 4.5, 6, 8, 10});
  const BeverlooFit ff = fit_beverloo(far.w, far.Q, far.Q_err), fs = fit_beverloo(spread.w, spread.Q, spread.Q_err);
  const DesignAdvice af = next_width(ff, far.w, far.Q, far.Q_err, 2.0, 12.0, 0.25);
  const DesignAdvice as = next_width(fs, spread.w, spread.Q, spread.Q_err, 2.0, 12.0, 0.25);
  EXPECT_GT(af.k_err_now, 3 * as.k_err_now);  // the bunched design is the poorly conditioned one
}

TEST(NextWidth, MetTargetsAskForNothingAndUnmetOnesForARun) {
  const Series s = exact({4, 5, 6, 7, 8, 9, 10});
  const BeverlooFit f = fit_beverloo(s.w, s.Q, s.Q_err);
  const DesignAdvice loose = next_width(f, s.w, s.Q, s.Q_err, 2.0, 12.0, 0.25, {10.0, 10.0});
  EXPECT_TRUE(loose.targets_met);
  EXPECT_FALSE(loose.next.has_value());
  const DesignAdvice tight = next_width(f, s.w, s.Q, s.Q_err, 2.0, 12.0, 0.25, {std::nullopt, 1e-4});
  EXPECT_FALSE(tight.targets_met);
  ASSERT_TRUE(tight.next.has_value());
  EXPECT_LT(tight.next->beta_err_after, tight.beta_err_now);
}

/// The runs of a series as FlowTimeCosts lists them: each run's window gives its 2 % error,
/// exits_rel2 = window Q (SE/Q)^2 the same for all.
FlowTimeCosts flow_costs(const Series& s, double start_t0, double exits_rel2 = 400 * 0.02 * 0.02) {
  FlowTimeCosts c;
  c.start_t0 = start_t0;
  c.exits_rel2 = exits_rel2;
  for (std::size_t i = 0; i < s.w.size(); ++i) c.runs.push_back({s.w[i], s.Q_err[i], exits_rel2 / (0.02 * 0.02 * s.Q[i])});
  return c;
}

TEST(NextWidth, MoreFlowTimeWinsWhereANewRunsStartCostsMoreThanItsWindow) {
  // the range allows no width the series has not got: a new run or more flow time, at its widths
  const Series s = exact({3, 4, 6, 8, 10});
  const BeverlooFit f = fit_beverloo(s.w, s.Q, s.Q_err);
  // no start to pay: a new run at a width and the same width's run extended add the same
  // information for the same flow; the tie goes to the new run (the run-to-run spread is worth
  // having), and the choice is the one without costs
  const FlowTimeCosts free_start = flow_costs(s, 0.0);
  const DesignAdvice plain = next_width(f, s.w, s.Q, s.Q_err, 3.0, 10.0, 1.0);
  const DesignAdvice tie = next_width(f, s.w, s.Q, s.Q_err, 3.0, 10.0, 1.0, {}, &free_start);
  ASSERT_TRUE(tie.next && plain.next);
  EXPECT_FALSE(tie.next->extend_run.has_value());
  EXPECT_EQ(tie.next->w, plain.next->w);
  EXPECT_NEAR(tie.next->k_err_after, plain.next->k_err_after, 1e-12);
  // a start as long as a window: the run at the chosen width is extended instead, with the
  // same predicted errors (the same information) at half the cost
  const FlowTimeCosts costly_start = flow_costs(s, 1e3);
  const DesignAdvice ext = next_width(f, s.w, s.Q, s.Q_err, 3.0, 10.0, 1.0, {}, &costly_start);
  ASSERT_TRUE(ext.next && ext.next->extend_run);
  const std::size_t i = *ext.next->extend_run;
  EXPECT_EQ(costly_start.runs[i].w, ext.next->w);
  EXPECT_LT(ext.next->k_err_after, ext.k_err_now);
  EXPECT_LT(ext.next->beta_err_after, ext.beta_err_now);
  EXPECT_NEAR(ext.next->relative_cost * (1e3 + costly_start.exits_rel2 / (0.02 * 0.02 * s.Q[2])),
              costly_start.runs[i].window_t0, 1e-9 * costly_start.runs[i].window_t0);
  // a run that cannot be extended (no error, or at or below k) is never chosen
  FlowTimeCosts none = costly_start;
  for (auto& r : none.runs) r.Q_err = 0;
  const DesignAdvice no_ext = next_width(f, s.w, s.Q, s.Q_err, 3.0, 10.0, 1.0, {}, &none);
  ASSERT_TRUE(no_ext.next);
  EXPECT_FALSE(no_ext.next->extend_run.has_value());
}

TEST(NextWidth, BadInputIsAFitErrorNotANumber) {
  const Series s = exact({6, 7, 8, 9, 10});
  const BeverlooFit f = fit_beverloo(s.w, s.Q, s.Q_err);
  EXPECT_THROW(next_width(f, {6, 7}, {1, 2}, {0.1, 0.1}, 2, 12, 0.25), FitError);
  EXPECT_THROW(next_width(f, s.w, s.Q, s.Q_err, 12, 2, 0.25), FitError);
  EXPECT_THROW(next_width(f, s.w, s.Q, s.Q_err, 2, 12, 0), FitError);
  EXPECT_THROW(next_width(f, s.w, s.Q, s.Q_err, 0.5, 1.6, 0.25), FitError);  // nothing above k
}

}  // namespace
}  // namespace beverloo
