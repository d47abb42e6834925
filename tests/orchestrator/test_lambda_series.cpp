// A new lambda in a beta(lambda) group (reports/lambda_series.h): placed on the axis the two
// nearest series share, for the text's axis and both branches of the authors'.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/config.h"
#include "engine/parameters.h"
#include "reports/lambda_series.h"

namespace beverloo {
namespace {
using nlohmann::json;

json canonical(const json& j) {
  SimConfig c = SimConfig::from_json(j);
  c.resolve_and_validate();
  return c.to_json();
}

double lambda_of(const json& j) { return *derived::lambda(SimConfig::from_json(j)); }

TEST(LambdaSeries, TheTextsAxisKeepsZetaAndSetsMu) {
  const derived::ZetaMu a = derived::on_lambda_axis(0.1, 1.0), b = derived::on_lambda_axis(1.0, 1.0);
  const json ja = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", a.zeta}, {"mu", a.mu}});
  const json jb = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", b.zeta}, {"mu", b.mu}});
  const LambdaJob made = job_at_lambda(ja, jb, 0.3);
  ASSERT_TRUE(made.job) << made.problem;
  EXPECT_EQ(made.job->at("zeta").get<double>(), a.zeta);
  EXPECT_NEAR(lambda_of(*made.job), 0.3, 1e-12);
  EXPECT_EQ(made.job->at("w").get<double>(), 5.0);  // a's width: the planner sets each width
}

TEST(LambdaSeries, TheAuthorsBranchesVaryTheDragRateOrTheFriction) {
  // branch 1: drag as a rate varied at a fixed friction (mu_n = 0: tangential only)
  const json f1 = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0}, {"mu", 8.5}, {"mu_n", 0}, {"drag_rate", 0.02}});
  const json f2 = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0}, {"mu", 8.5}, {"mu_n", 0}, {"drag_rate", 0.2}});
  const LambdaJob d = job_at_lambda(f1, f2, 0.01);
  ASSERT_TRUE(d.job) << d.problem;
  EXPECT_EQ(d.job->at("mu").get<double>(), 8.5);
  EXPECT_EQ(d.job->at("zeta").get<double>(), 0.0);
  EXPECT_NEAR(lambda_of(*d.job), 0.01, 1e-12);
  // branch 2: friction varied at a fixed drag rate
  const json g1 = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0}, {"mu", 4.25}, {"mu_n", 0}, {"drag_rate", 1.96}});
  const json g2 = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0}, {"mu", 0.85}, {"mu_n", 0}, {"drag_rate", 1.96}});
  const LambdaJob m = job_at_lambda(g2, g1, 1.0);
  ASSERT_TRUE(m.job) << m.problem;
  EXPECT_EQ(m.job->at("drag_rate").get<double>(), 1.96);
  EXPECT_EQ(m.job->at("mu_n").get<double>(), 0.0);
  EXPECT_NEAR(lambda_of(*m.job), 1.0, 1e-12);
}

TEST(LambdaSeries, SeriesDifferingInBothHaveNoAxis) {
  const json a = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0.1}, {"mu", 1.0}});
  const json b = canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0.2}, {"mu", 0.5}});
  const LambdaJob made = job_at_lambda(a, b, 0.2);
  EXPECT_FALSE(made.job);
  EXPECT_NE(made.problem.find("differ in both"), std::string::npos) << made.problem;
  EXPECT_FALSE(job_at_lambda(a, a, 0).job);  // lambda must be > 0
}

TEST(LambdaSeries, TheGroupsLimitsBracketBeyondItsEnds) {
  // the authors' first branch (drag rate varied at mu 8.5) with both limits of the group
  auto sp = [](double mu, double rate) {
    return canonical({{"N", 50}, {"W", 12}, {"w", 5}, {"zeta", 0}, {"mu", mu}, {"mu_n", 0}, {"drag_rate", rate}});
  };
  const json f1 = sp(8.5, 0.02), f2 = sp(8.5, 1.96), lim0 = sp(8.5, 0), lim_inf = sp(0, 1.96);
  LambdaGroupJobs group;
  group.finite = {{lambda_of(f1), f1}, {lambda_of(f2), f2}};
  const double top = lambda_of(f2), bottom = lambda_of(f1);
  // beyond the top without the lambda = inf series: the last two series' axis, the drag raised
  LambdaJob up = job_at_lambda_in_group(group, 4 * top);
  ASSERT_TRUE(up.job) << up.problem;
  EXPECT_GT(up.job->at("drag_rate").get<double>(), 1.96);
  // with it: the friction lowered at the top series' drag (the authors' second branch)
  group.limit_inf = &lim_inf;
  up = job_at_lambda_in_group(group, 4 * top);
  ASSERT_TRUE(up.job) << up.problem;
  EXPECT_EQ(up.job->at("drag_rate").get<double>(), 1.96);
  EXPECT_NEAR(up.job->at("mu").get<double>(), 8.5 / 4, 1e-12);
  EXPECT_NEAR(lambda_of(*up.job), 4 * top, 1e-9 * top);
  // between two series the limits play no part
  const LambdaJob mid = job_at_lambda_in_group(group, std::sqrt(top * bottom));
  ASSERT_TRUE(mid.job) << mid.problem;
  EXPECT_EQ(mid.job->at("mu").get<double>(), 8.5);
  // below the bottom with the lambda = 0 series (the same friction): the drag lowered
  group.limit0 = &lim0;
  const LambdaJob down = job_at_lambda_in_group(group, bottom / 10);
  ASSERT_TRUE(down.job) << down.problem;
  EXPECT_EQ(down.job->at("mu").get<double>(), 8.5);
  EXPECT_NEAR(down.job->at("drag_rate").get<double>(), 0.002, 1e-15);
  // a lambda = inf series at another drag shares nothing with the top: the last two series again
  const json other_inf = sp(0, 0.5);
  group.limit_inf = &other_inf;
  up = job_at_lambda_in_group(group, 4 * top);
  ASSERT_TRUE(up.job) << up.problem;
  EXPECT_EQ(up.job->at("mu").get<double>(), 8.5);
  EXPECT_GT(up.job->at("drag_rate").get<double>(), 1.96);
}

}  // namespace
}  // namespace beverloo
