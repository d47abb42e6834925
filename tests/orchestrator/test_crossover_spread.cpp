// The run-to-run spread of a crossover beta(lambda) (reports/crossover_groups.h): the sigmoid
// fitted again to each replica's own exponents, over the pooled fit's lambdas.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reports/crossover_groups.h"
#include "reports/series_fits.h"

namespace beverloo {
namespace {

const std::vector<double> kLambdas = {0.003, 0.01, 0.03, 0.1, 0.3, 1};
/// Each replica's own crossover: lambda_c = 0.03, 0.05, 0.08 with b = 0.8 and the paper's 2D
/// plateaus, so every replica's exponents lie exactly on its own sigmoid.
const double kLambdaC[] = {0.03, 0.05, 0.08};

/// The text's lambda axis (zeta = 1, mu = 1 / lambda): one series per lambda, replicas 0-2 whose
/// flow follows Q = 5 (w - 1.5)^beta_r(lambda) exactly (1 % errors) at w = 4..10.
/// skip_replica: a replica left out of the series at lambda = 0.03 (-1: none).
std::vector<Series> three_replica_group(int skip_replica) {
  std::vector<Series> out;
  for (double lambda : kLambdas) {
    Series s;
    s.dimension = 2, s.N = 1600, s.zeta = 1, s.mu = 1 / lambda, s.lambda = lambda;
    s.key = "series lambda=" + std::to_string(lambda);
    s.base_key = s.angle_free_key = "2D SP";
    std::vector<RunRecord> runs;
    for (int r = 0; r < 3; ++r) {
      if (r == skip_replica && lambda == 0.03) continue;
      const double beta = crossover_model(2, lambda, kLambdaC[r], 0.8);
      for (double w = 4; w <= 10; w += 1) {
        RunRecord run;
        run.w = w, run.replica = r;
        run.Q = 5 * std::pow(w - 1.5, beta);
        run.Q_err = 0.01 * run.Q;
        runs.push_back(run);
      }
    }
    fit_series(s, runs);
    out.push_back(s);
  }
  return out;
}

/// One series on the text's lambda axis (zeta = 1, mu = 1 / lambda), one run per width whose
/// flow follows Q = 5 (w - 1.5)^beta exactly (1 % errors) at w = 4..10, fitted.
Series one_run_series(double lambda, double beta) {
  Series s;
  s.dimension = 2, s.N = 1600, s.zeta = 1, s.mu = 1 / lambda, s.lambda = lambda;
  s.key = "series lambda=" + std::to_string(lambda);
  s.base_key = s.angle_free_key = "2D SP";
  std::vector<RunRecord> runs;
  for (double w = 4; w <= 10; w += 1) {
    RunRecord run;
    run.w = w;
    run.Q = 5 * std::pow(w - 1.5, beta);
    run.Q_err = 0.01 * run.Q;
    runs.push_back(run);
  }
  fit_series(s, runs);
  return s;
}

std::map<std::string, nlohmann::json> base_jobs(const std::vector<Series>& series) {
  std::map<std::string, nlohmann::json> out;
  for (const Series& s : series) out[s.key] = nlohmann::json::object();
  return out;
}

double sample_sd_of_log10(std::vector<double> v) {
  for (double& x : v) x = std::log10(x);
  return sample_sd(v);
}

TEST(CrossoverSpread, EachReplicasOwnSigmoidGivesTheSpreadOfLog10LambdaC) {
  const std::vector<Series> series = three_replica_group(-1);
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  const Crossover& g = groups.front();
  ASSERT_TRUE(g.fit);
  EXPECT_EQ(g.spread.replicas, 3);
  const double expected = sample_sd_of_log10({0.03, 0.05, 0.08});  // 0.213 decades
  EXPECT_NEAR(g.spread.log10_lambda_c, expected, 1e-3);
  EXPECT_NEAR(g.spread.b, 0, 1e-3);  // every replica has b = 0.8
  EXPECT_EQ(g.spread_free.replicas, 3);
  EXPECT_NEAR(g.spread_free.log10_lambda_c, expected, 1e-2);
  // the pooled fit's own error knows nothing of this: it is far smaller than the spread
  EXPECT_LT(g.fit->log10_lambda_c_err, expected / 3);
}

TEST(CrossoverSpread, AReplicaMissingFromOneLambdaIsLeftOutAndOneReplicaGivesNone) {
  const std::vector<Series> series = three_replica_group(2);
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups.front().spread.replicas, 2);
  EXPECT_NEAR(groups.front().spread.log10_lambda_c, sample_sd_of_log10({0.03, 0.05}), 1e-3);

  std::vector<Series> lone = three_replica_group(-1);
  for (Series& s : lone) s.replica_fit.erase(1), s.replica_fit.erase(2);
  const std::vector<Crossover> lone_groups = crossover_groups(lone, base_jobs(lone));
  ASSERT_EQ(lone_groups.size(), 1u);
  EXPECT_TRUE(std::isnan(lone_groups.front().spread.log10_lambda_c));
  EXPECT_EQ(lone_groups.front().spread.replicas, 0);
}

TEST(CrossoverSpread, ALambdaRunOnceIsLeftOutOfTheReplicasFitsAndCounted) {
  // lambda = 0.03 with replica 0 only (a costly lambda run once, as the text set's Fig. 4a runs
  // lambda = 1e-3): the other five lambdas still give each replica its own sigmoid
  std::vector<Series> series = three_replica_group(-1);
  for (Series& s : series)
    if (s.lambda == 0.03) s.replica_fit.erase(1), s.replica_fit.erase(2);
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  const Crossover& g = groups.front();
  EXPECT_EQ(g.spread.replicas, 3);
  EXPECT_EQ(g.spread.lambdas_left_out, 1);
  EXPECT_EQ(g.spread_free.lambdas_left_out, 1);
  EXPECT_NEAR(g.spread.log10_lambda_c, sample_sd_of_log10({0.03, 0.05, 0.08}), 1e-3);
  EXPECT_NE(lambda_c_spread_phrase(g.spread).find("over 3 replicas, leaving out 1 lambda with fewer than two replica fits"),
            std::string::npos)
      << lambda_c_spread_phrase(g.spread);
  // with every lambda replicated the phrase says nothing more
  const std::vector<Series> intact = three_replica_group(-1);
  const std::vector<Crossover> whole = crossover_groups(intact, base_jobs(intact));
  EXPECT_EQ(whole.front().spread.lambdas_left_out, 0);
  EXPECT_EQ(lambda_c_spread_phrase(whole.front().spread).find("leaving out"), std::string::npos);
  // fewer than three replicated lambdas fix no sigmoid: no spread
  std::vector<Series> sparse = three_replica_group(-1);
  for (std::size_t i = 0; i < 4; ++i) sparse[i].replica_fit.erase(1), sparse[i].replica_fit.erase(2);
  const std::vector<Crossover> none = crossover_groups(sparse, base_jobs(sparse));
  EXPECT_EQ(none.front().spread.replicas, 0);
  EXPECT_TRUE(std::isnan(none.front().spread.log10_lambda_c));
}

TEST(CrossoverFitOfAGroup, AStepSharperThanTheLambdasResolveIsNotDetermined) {
  // three lambdas where the paper's sigmoid matches the one point on the step exactly as b -> 0,
  // with a singular covariance: no lambda_c is reported
  std::vector<Series> series;
  const std::vector<std::pair<double, double>> at = {{1e-3, 1.5}, {1e-2, 1.2}, {1e-1, 0.5}};
  for (const auto& [lambda, beta] : at) series.push_back(one_run_series(lambda, beta));
  // the exponents of the DP Fig. 6a campaign at 20 deg (docs/paper.md): the lowest lambda's
  // free fit is undetermined (6.2 +- 6.5), the step between the other two is matched exactly
  const double measured[3][2] = {{6.217, 6.5}, {1.198, 0.079}, {0.4734, 0.09}};
  for (int i = 0; i < 3; ++i) series[i].fit->beta = measured[i][0], series[i].fit->beta_err = measured[i][1];
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_FALSE(groups.front().fit) << "lambda_c " << groups.front().fit->lambda_c << " +- "
                                   << groups.front().fit->lambda_c_err << ", b " << groups.front().fit->b << " +- "
                                   << groups.front().fit->b_err;
  EXPECT_EQ(groups.front().message.rfind("not determined: a singular fit", 0), 0u) << groups.front().message;
  // a step the lambdas do resolve keeps its fit (the spread tests above), and so does this one
  // with its middle exponent on a gentle slope
  for (int i = 0; i < 3; ++i) series[i].fit->beta = crossover_model(2, at[i].first, 0.03, 0.8), series[i].fit->beta_err = 0.05;
  const std::vector<Crossover> gentle = crossover_groups(series, base_jobs(series));
  ASSERT_TRUE(gentle.front().fit) << gentle.front().message;
  EXPECT_NEAR(gentle.front().fit->lambda_c, 0.03, 1e-4);
}

TEST(CrossoverFitOfAGroup, AFreePlateauFitWithAnErrorOfManyDecadesIsNotDetermined) {
  // the DP Fig. 6a campaign at 30 deg (docs/paper.md, five lambdas): three exponents on the
  // friction side, then a step with no point inside it; the free-plateau sigmoid matched it with
  // lambda_c = 0.031 +- 1e12, which is no measurement. The paper's sigmoid keeps its fit.
  const double measured[5][3] = {
      {1e-3, 1.21, 0.069}, {1e-2, 1.271, 0.077}, {0.01778, 1.323, 0.11}, {0.03162, 0.6943, 0.05}, {0.1, 0.4652, 0.1}};
  std::vector<Series> series;
  for (const auto& [lambda, beta, beta_err] : measured) {
    series.push_back(one_run_series(lambda, beta));
    series.back().fit->beta = beta, series.back().fit->beta_err = beta_err;
  }
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  const Crossover& g = groups.front();
  EXPECT_FALSE(g.fit_free) << "lambda_c " << g.fit_free->lambda_c << " +- " << g.fit_free->lambda_c_err;
  EXPECT_EQ(g.message_free.rfind("not determined: a singular fit", 0), 0u) << g.message_free;
  ASSERT_TRUE(g.fit) << g.message;
  EXPECT_GT(g.fit->lambda_c, 0.0178);
  EXPECT_LT(g.fit->lambda_c, 0.0316);
  EXPECT_LT(g.fit->log10_lambda_c_err, 0.1);
}

TEST(CrossoverFitOfAGroup, ASeriesThatFollowsNoBeverlooLawStaysOutOfTheSigmoid) {
  // six lambdas on the replicas' sigmoids; then the lowest one's fit made that of a Q(w) that
  // follows no Beverloo law with k >= 0 (Fig. 6a's DP at 90 deg, lambda = 1e-3: beta 3.4 with
  // k = -6), with a small error, so that taking it would pull the sigmoid far
  std::vector<Series> series = three_replica_group(-1);
  const std::vector<Crossover> intact = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(intact.size(), 1u);
  ASSERT_TRUE(intact.front().fit && intact.front().fit_free);
  EXPECT_TRUE(intact.front().no_beverloo_law.empty());
  Series& odd = series.front();
  ASSERT_EQ(odd.lambda, kLambdas.front());
  odd.fit->beta = 3.4, odd.fit->beta_err = 0.06, odd.fit->k = -6;
  ASSERT_TRUE(follows_no_beverloo_law(odd));
  const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  ASSERT_EQ(groups.size(), 1u);
  const Crossover& g = groups.front();
  ASSERT_EQ(g.no_beverloo_law.size(), 1u);
  EXPECT_EQ(g.no_beverloo_law.front(), &series.front());
  EXPECT_EQ(g.finite.size(), kLambdas.size());  // still the group's, drawn and listed
  EXPECT_EQ(g.fitted_points(), static_cast<int>(kLambdas.size()) - 1);
  ASSERT_TRUE(g.fit) << g.message;
  // the five others fix the fits: lambda_c within 0.05 decades of the intact group's, and the
  // free plateau at lambda -> 0 is not pulled up towards the odd point's 3.4
  EXPECT_NEAR(g.fit->log10_lambda_c, intact.front().fit->log10_lambda_c, 0.05);
  ASSERT_TRUE(g.fit_free) << g.message_free;
  EXPECT_NEAR(g.fit_free->beta_0, intact.front().fit_free->beta_0, 0.1);

  // with too few series left the fit says why, naming the lambda left out
  std::vector<Series> three(series.begin(), series.begin() + 3);
  const std::vector<Crossover> few = crossover_groups(three, base_jobs(three));
  ASSERT_EQ(few.size(), 1u);
  EXPECT_FALSE(few.front().fit);
  EXPECT_NE(few.front().message.find("no Beverloo law at lambda = 0.003"), std::string::npos) << few.front().message;
}

TEST(CrossoverFitOfAGroup, AKWithinTwoErrorsOfTheRangeIsABeverlooLawAndStaysIn) {
  // k = -0.5 +- 0.3 is a Beverloo law whose k the widths do not pin (1.7 errors below 0); with
  // k's error 0.2 it is 2.5 errors below and leaves the sigmoid. At the top: the smallest
  // flowing width is 4, and k = 4.3 +- 0.2 stays, 4.5 +- 0.2 leaves. Without an error there is
  // no tolerance.
  std::vector<Series> series = three_replica_group(-1);
  Series& odd = series.front();
  auto left_out = [&](double k, double k_err) {
    odd.fit->k = k, odd.fit->k_err = k_err;
    const std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
    EXPECT_EQ(groups.size(), 1u);
    const bool out = !groups.front().no_beverloo_law.empty();
    EXPECT_EQ(out, follows_no_beverloo_law(odd)) << k << " +- " << k_err;
    EXPECT_EQ(out, fit_quality(odd) != "ok") << fit_quality(odd);
    return out;
  };
  EXPECT_FALSE(left_out(-0.5, 0.3));
  EXPECT_TRUE(left_out(-0.5, 0.2));
  EXPECT_FALSE(left_out(4.3, 0.2));
  EXPECT_TRUE(left_out(4.5, 0.2));
  EXPECT_TRUE(left_out(-0.01, NAN));
  left_out(-0.5, 0.2);
  EXPECT_EQ(fit_quality(odd), "not determined: k = -0.5 +- 0.2, outside [0, smallest w] by more than 2 errors");
}

/// One group whose exponents lie exactly on beta(x) at lambda = 10^(x_c + offset), x_c = log10 0.03.
template <class Beta>
Crossover crossing_group(std::vector<Series>& series, const std::vector<double>& offsets, Beta beta_of) {
  const double x_c = std::log10(0.03);
  series.clear();
  for (const double dx : offsets) {
    series.push_back(one_run_series(std::pow(10.0, x_c + dx), beta_of(dx)));
    series.back().fit->beta = beta_of(dx), series.back().fit->beta_err = 0.05;
  }
  std::vector<Crossover> groups = crossover_groups(series, base_jobs(series));
  EXPECT_EQ(groups.size(), 1u);
  return groups.front();
}

TEST(MidpointCrossing, TheInterpolationsErrorIsWhatAParabolaThroughANeighbourMovesTheChordsCrossing) {
  const double x_c = std::log10(0.03);
  // beta = 1 - 0.8 dx + 0.4 dx^2 crosses 1 at dx = 0; the chord between dx = -0.35 and 0.2
  // crosses at dx = 0.55 * 0.329 / 0.473 = 0.0326, and either neighbour's parabola is beta itself
  auto curved = [](double dx) { return 1 - 0.8 * dx + 0.4 * dx * dx; };
  std::vector<Series> series;
  const Crossover g = crossing_group(series, {-0.9, -0.35, 0.2, 0.75}, curved);
  const auto m = crossing_of_d_minus_1(g);
  ASSERT_TRUE(m);
  const double chord_error = m->log10_lambda - x_c;
  EXPECT_NEAR(chord_error, 0.55 * 0.329 / 0.473 - 0.35, 1e-9);
  EXPECT_NEAR(m->interpolation, chord_error, 1e-9) << "a parabola through three points of a parabola is exact";
  EXPECT_NEAR(m->verdict_sigma(), std::hypot(m->sigma, chord_error), 1e-12);
  // a grid of half the step: the chord's error, and the estimate with it, a quarter
  const Crossover fine = crossing_group(series, {-0.45, -0.175, 0.1, 0.375}, curved);
  const auto m_fine = crossing_of_d_minus_1(fine);
  ASSERT_TRUE(m_fine);
  EXPECT_NEAR(m_fine->interpolation, m_fine->log10_lambda - x_c, 1e-9);
  EXPECT_NEAR(m_fine->interpolation / m->interpolation, 0.25, 0.03);
  // a straight beta(log10 lambda): the chord is right and the estimate nothing
  const Crossover straight = crossing_group(series, {-0.9, -0.35, 0.2, 0.75}, [](double dx) { return 1 - 0.8 * dx; });
  const auto m_straight = crossing_of_d_minus_1(straight);
  ASSERT_TRUE(m_straight);
  EXPECT_NEAR(m_straight->log10_lambda, x_c, 1e-12);
  EXPECT_LT(m_straight->interpolation, 1e-12);
  // the bracketing pair alone: nothing to estimate it with, and the verdict's sigma is the scatter's
  const Crossover pair = crossing_group(series, {-0.35, 0.2}, curved);
  const auto m_pair = crossing_of_d_minus_1(pair);
  ASSERT_TRUE(m_pair);
  EXPECT_TRUE(std::isnan(m_pair->interpolation));
  EXPECT_DOUBLE_EQ(m_pair->verdict_sigma(), m_pair->sigma);
  // monotone: nothing turns back
  EXPECT_TRUE(std::isnan(m->reversal_z));
  // beta turning back above the pair (the authors' SP model at 30 deg: 1.04, 0.73, then 0.95):
  // the step 0.73 -> 0.95 goes against the pair's fall by 0.22 / (0.05 sqrt 2) = 3.1 sigma
  const std::map<double, double> turning = {{-0.9, 1.25}, {-0.35, 1.044}, {0.2, 0.732}, {0.75, 0.952}};
  const Crossover turns = crossing_group(series, {-0.9, -0.35, 0.2, 0.75}, [&](double dx) { return turning.at(dx); });
  const auto m_turns = crossing_of_d_minus_1(turns);
  ASSERT_TRUE(m_turns);
  EXPECT_NEAR(m_turns->reversal_z, 0.22 / (0.05 * std::sqrt(2.0)), 1e-9);
  // a neighbour on one side only (the crossing in the first interval): its one parabola
  const Crossover first = crossing_group(series, {-0.35, 0.2, 0.75}, curved);
  const auto m_first = crossing_of_d_minus_1(first);
  ASSERT_TRUE(m_first);
  EXPECT_NEAR(m_first->interpolation, chord_error, 1e-9);
}

}  // namespace
}  // namespace beverloo
