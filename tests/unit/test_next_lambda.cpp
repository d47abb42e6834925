// Where the next lambda series of a beta(lambda) group helps the crossover fit most
// (reports/next_lambda.h).
#include <gtest/gtest.h>

#include <cmath>

#include "reports/fit.h"
#include "reports/next_lambda.h"

namespace beverloo {
namespace {

struct Group {
  std::vector<double> lambda, beta, beta_err;
};

/// Exact beta(lambda) of the paper's law in 2D with errors 0.04 at the given lambdas.
Group exact(const std::vector<double>& lambdas, double lambda_c = 0.1, double b = 0.5) {
  Group g;
  for (double l : lambdas) {
    g.lambda.push_back(l);
    g.beta.push_back(crossover_model(2, l, lambda_c, b));
    g.beta_err.push_back(0.04);
  }
  return g;
}

TEST(NextLambda, ANewSeriesGoesOnTheStepAndLowersTheErrors) {
  // series far on both sides of lambda_c = 0.1 and one near it: the step is poorly sampled
  const Group g = exact({1e-4, 1e-3, 0.05, 10, 100});
  const CrossoverFit f = fit_crossover(2, g.lambda, g.beta, g.beta_err);
  const CrossoverAdvice a = next_lambda(2, f, g.lambda, g.beta_err, 1e-4, 100, 4);
  ASSERT_TRUE(a.next.has_value());
  EXPECT_NEAR(a.log10_lambda_c_err_now, f.log10_lambda_c_err, 1e-12);
  EXPECT_LT(a.next->log10_lambda_c_err_after, a.log10_lambda_c_err_now);
  EXPECT_LT(a.next->b_err_after, a.b_err_now);
  // on the grid, not a lambda the group has, within a decade of lambda_c where beta is steep
  const double k = std::log10(a.next->lambda) * 4;
  EXPECT_NEAR(k, std::round(k), 1e-9);
  EXPECT_GT(std::fabs(std::log10(a.next->lambda / 0.05)), 0.125);
  EXPECT_LT(std::fabs(std::log10(a.next->lambda / 0.1)), 1.0) << a.next->lambda;
  // deterministic
  const CrossoverAdvice again = next_lambda(2, f, g.lambda, g.beta_err, 1e-4, 100, 4);
  EXPECT_EQ(again.next->lambda, a.next->lambda);
}

TEST(NextLambda, ALambdaTheGroupHasWithoutAFitIsNotProposedAgain) {
  // the planner's case (runs/fig4a_adaptive, 2026-12-04): a series added at the best lambda that
  // could not be fitted (one flowing width) was proposed again, the same jobs, and the group
  // stalled; given with error 0 it adds no information but holds its lambda
  const Group g = exact({1e-4, 1e-3, 0.05, 10, 100});
  const CrossoverFit f = fit_crossover(2, g.lambda, g.beta, g.beta_err);
  const CrossoverAdvice first = next_lambda(2, f, g.lambda, g.beta_err, 1e-4, 100, 4);
  ASSERT_TRUE(first.next.has_value());
  std::vector<double> lambda = g.lambda, err = g.beta_err;
  lambda.push_back(first.next->lambda);
  err.push_back(0);
  const CrossoverAdvice second = next_lambda(2, f, lambda, err, 1e-4, 100, 4);
  ASSERT_TRUE(second.next.has_value());
  EXPECT_GT(std::fabs(std::log10(second.next->lambda / first.next->lambda)), 0.125) << second.next->lambda;
  EXPECT_NEAR(second.log10_lambda_c_err_now, first.log10_lambda_c_err_now, 1e-12) << "no information from it";
}

TEST(NextLambda, TargetsMetStopAndAMissingTargetWeighsByThePresentError) {
  const Group g = exact({0.01, 0.03, 0.1, 0.3, 1});
  const CrossoverFit f = fit_crossover(2, g.lambda, g.beta, g.beta_err);
  CrossoverTargets loose;
  loose.log10_lambda_c_err = 10 * f.log10_lambda_c_err;
  EXPECT_TRUE(next_lambda(2, f, g.lambda, g.beta_err, 1e-3, 10, 4, loose).targets_met);
  EXPECT_FALSE(next_lambda(2, f, g.lambda, g.beta_err, 1e-3, 10, 4, loose).next.has_value());
  CrossoverTargets tight;
  tight.log10_lambda_c_err = 0.1 * f.log10_lambda_c_err;
  const CrossoverAdvice a = next_lambda(2, f, g.lambda, g.beta_err, 1e-3, 10, 4, tight);
  EXPECT_FALSE(a.targets_met);
  ASSERT_TRUE(a.next.has_value());
  EXPECT_LT(a.next->log10_lambda_c_err_after, a.log10_lambda_c_err_now);
}

TEST(NextLambda, AStepBetweenSeriesIsRefinedAtLambdaC) {
  // a step far sharper than the series' spacing: no information on (lambda_c, b) is left
  CrossoverFit f;
  f.log10_lambda_c = std::log10(0.9);
  f.log10_lambda_c_err = 0.004;
  f.b = 0.04;
  f.b_err = 0;
  const std::vector<double> lambda = {0.01, 0.1, 1}, err = {0.05, 0.05, 0.05};
  const CrossoverAdvice a = next_lambda(2, f, lambda, err, 1e-3, 10, 4);
  ASSERT_TRUE(a.next.has_value());
  EXPECT_NEAR(a.next->lambda, std::pow(10.0, -0.25), 1e-12);  // the free candidate nearest log10 0.9
  EXPECT_TRUE(std::isnan(a.next->log10_lambda_c_err_after));
}

TEST(NextLambda, RefusesWhatCannotBeDesigned) {
  const Group g = exact({0.01, 0.1, 1});
  const CrossoverFit f = fit_crossover(2, g.lambda, g.beta, g.beta_err);
  EXPECT_THROW(next_lambda(2, f, {0.01, 0.1}, {0.04, 0.04}, 1e-3, 10, 4), FitError);         // too few series
  EXPECT_THROW(next_lambda(2, f, g.lambda, g.beta_err, 0, 10, 4), FitError);                 // no range
  EXPECT_THROW(next_lambda(2, f, g.lambda, g.beta_err, 0.01, 0.01, 1), FitError);            // every candidate taken
}

}  // namespace
}  // namespace beverloo
