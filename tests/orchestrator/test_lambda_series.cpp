// A new lambda in a beta(lambda) group (reports/lambda_series.h): placed on the axis the two
// nearest series share, for the text's axis and both branches of the authors'.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace beverloo
