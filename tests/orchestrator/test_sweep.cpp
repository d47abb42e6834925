// The sweep language: exact job sets for every construct, errors that name the JSON path,
// and job keys that are stable (golden values) and sensitive to every parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "engine/parameters.h"
#include "orchestrator/sweep/sweep.h"
#include "core/version.h"

namespace beverloo {
namespace {
using nlohmann::json;

std::vector<JobSpec> expand(const json& j) { return Sweep::parse(j).expand(); }
json base() { return {{"N", 50}, {"W", 12}, {"zeta", 0.3}, {"mu", 0.0}}; }

/// The jobs as a list of (param -> value) restricted to the given names, in expansion order.
std::vector<std::map<std::string, double>> table(const std::vector<JobSpec>& jobs, const std::vector<std::string>& names) {
  std::vector<std::map<std::string, double>> out;
  for (const JobSpec& j : jobs) {
    std::map<std::string, double> row;
    for (const auto& n : names) {
      const json& v = j.job.contains(n) ? j.job[n] : j.job["run"][n.substr(4)];
      row[n] = v.get<double>();
    }
    out.push_back(row);
  }
  return out;
}

TEST(Sweep, ProductVariesTheFirstAxisSlowest) {
  const auto jobs = expand({{"base", base()}, {"sweep", {{"product", {{{"w", {3, 4}}}, {{"E_sp", {100, 1000, 1e4}}}}}}}});
  const std::vector<std::map<std::string, double>> expected = {
      {{"w", 3}, {"E_sp", 100}}, {{"w", 3}, {"E_sp", 1000}}, {{"w", 3}, {"E_sp", 1e4}},
      {{"w", 4}, {"E_sp", 100}}, {{"w", 4}, {"E_sp", 1000}}, {{"w", 4}, {"E_sp", 1e4}}};
  EXPECT_EQ(table(jobs, {"w", "E_sp"}), expected);
  // several keys in one node are their product too
  EXPECT_EQ(table(expand({{"base", base()}, {"sweep", {{"E_sp", {100, 1000, 1e4}}, {"w", {3, 4}}}}}), {"w", "E_sp"}).size(), 6u);
}

TEST(Sweep, ZipPairsPointsAndRefusesUnequalLengths) {
  const auto jobs = expand({{"base", base()}, {"sweep", {{"zip", {{{"w", {3, 4, 5}}}, {{"E_sp", {10, 20, 30}}}}}}}});
  const std::vector<std::map<std::string, double>> expected = {
      {{"w", 3}, {"E_sp", 10}}, {{"w", 4}, {"E_sp", 20}}, {{"w", 5}, {"E_sp", 30}}};
  EXPECT_EQ(table(jobs, {"w", "E_sp"}), expected);
  try {
    (void)expand({{"base", base()}, {"sweep", {{"zip", {{{"w", {3, 4, 5}}}, {{"E_sp", {10, 20}}}}}}}});
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_EQ(e.path(), "sweep.zip[1]");
  }
}

TEST(Sweep, UnionConcatenatesAndDuplicateJobsRunOnce) {
  const auto jobs = expand({{"base", base()},
                            {"sweep", {{"union", {{{"w", {3, 4}}}, {{"w", {4, 5}}}, {{"w", 6}, {"E_sp", 50}}}}}}});
  const std::vector<std::map<std::string, double>> expected = {
      {{"w", 3}, {"E_sp", 100}}, {{"w", 4}, {"E_sp", 100}}, {{"w", 5}, {"E_sp", 100}}, {{"w", 6}, {"E_sp", 50}}};
  EXPECT_EQ(table(jobs, {"w", "E_sp"}), expected);
}

TEST(Sweep, RangesAreExactAtTheirEnds) {
  const auto lin = expand({{"base", base()}, {"sweep", {{"w", {{"linspace", {3, 5, 5}}}}}}});
  EXPECT_EQ(table(lin, {"w"}), (std::vector<std::map<std::string, double>>{{{"w", 3}}, {{"w", 3.5}}, {{"w", 4}}, {{"w", 4.5}}, {{"w", 5}}}));
  const auto log = expand({{"base", base()}, {"sweep", {{"w", 4}, {"E_sp", {{"logspace", {1, 3, 3}}}}}}});
  EXPECT_EQ(table(log, {"E_sp"}), (std::vector<std::map<std::string, double>>{{{"E_sp", 10}}, {{"E_sp", 100}}, {{"E_sp", 1000}}}));
  const auto geo = expand({{"base", base()}, {"sweep", {{"w", 4}, {"E_sp", {{"geomspace", {20, 80, 3}}}}}}});
  EXPECT_NEAR(table(geo, {"E_sp"})[1]["E_sp"], 40, 1e-12);
  EXPECT_EQ(table(geo, {"E_sp"})[2]["E_sp"], 80);
}

TEST(Sweep, LambdaLimitsAndDissipationScaleFollowPhysicsSpec) {
  const json b = {{"N", 50}, {"W", 12}, {"w", 4}};
  const auto jobs = expand({{"base", b}, {"sweep", {{"product", {{{"dissipation_scale", {1, 10}}}, {{"lambda", {0, 0.01, "inf"}}}}}}}});
  ASSERT_EQ(jobs.size(), 6u);
  const double z = 1 / std::sqrt(10.0);
  EXPECT_EQ(jobs[0].config.zeta, 0);                            // lambda = 0: friction only
  EXPECT_DOUBLE_EQ(jobs[0].config.mu, 10 * std::sqrt(10.0));
  EXPECT_DOUBLE_EQ(jobs[1].config.zeta, z);                     // lambda = 0.01: mu = zeta/lambda
  EXPECT_DOUBLE_EQ(jobs[1].config.mu, z / 0.01);
  EXPECT_NEAR(jobs[1].config.mu, 10 * std::sqrt(10.0), 1e-12);  // = the friction-only value
  EXPECT_DOUBLE_EQ(jobs[2].config.zeta, z);                     // lambda = inf: drag only
  EXPECT_EQ(jobs[2].config.mu, 0);
  EXPECT_DOUBLE_EQ(jobs[4].config.zeta, 10 * z);                // scale 10 multiplies both
  EXPECT_DOUBLE_EQ(jobs[4].config.mu, 10 * z / 0.01);
  EXPECT_TRUE(std::isinf(*jobs[2].lambda));
  // the crossover fits find a group's scale back from its zeta, and its lambda = 0 limit's
  // from mu (reports/crossover_groups.cpp): the inverse of the axis at every scale
  for (const double scale : {0.1, 1.0, 10.0}) {
    EXPECT_NEAR(derived::axis_scale_of_zeta(derived::on_lambda_axis(0.01, scale).zeta), scale, 1e-14 * scale);
    EXPECT_NEAR(derived::axis_scale_of_friction_limit(derived::on_lambda_axis(0, scale).mu), scale, 1e-14 * scale);
    EXPECT_EQ(derived::on_lambda_axis(INFINITY, scale).mu, 0);
  }
}

TEST(Sweep, EveryJobsLambdaIsTheDefinitionOfItsOwnParameters) {
  // lambda = (zeta + drag_rate M(sigma_avg)) / mu_t for every job, however the sweep sets it
  const json b = {{"N", 50}, {"W", 12}, {"w", 4}};
  const std::string base_text = R"("base": {"N": 50, "W": 12, "w": 4})";
  std::vector<json> ways;
  for (const char* rest : {R"("sweep": {"lambda": [0, 0.01, 0.5, "inf"]})",
                           R"("sweep": {"product": [{"dissipation_scale": [0.1, 10]}, {"lambda": [0.02, 3]}]})",
                           R"("sweep": {"product": [{"zeta": [0.1, 1]}, {"mu": [0, 2]}]})",
                           R"("derived": {"mu_t": "1 / lambda", "mu": "1 / lambda", "zeta": "0 * lambda + 1"}, "sweep": {"lambda": [0.5, 2]})",
                           R"("sweep": {"product": [{"drag_rate": [0, 1.96]}, {"zeta": [0]}, {"mu": [1]}, {"mu_n": [0]}]})"})
    ways.push_back(json::parse("{" + base_text + ", " + rest + "}"));
  int checked = 0;
  for (const json& sweep : ways)
    for (const JobSpec& j : expand(sweep)) {
      const std::optional<double> definition = derived::lambda(j.config);
      ASSERT_TRUE(definition.has_value()) << j.job.dump();
      if (j.lambda) {  // the axis' value is the job's
        if (std::isinf(*j.lambda)) EXPECT_TRUE(std::isinf(*definition)) << j.job.dump();
        else EXPECT_NEAR(*definition, *j.lambda, 1e-12 * std::max(1.0, *j.lambda)) << j.job.dump();
      }
      ++checked;
    }
  EXPECT_EQ(checked, 16);
  // a lambda axis that fixed mu_t or drag_rate would override is refused at the axis, not
  // stored as a lambda the jobs do not have
  for (const json& fixed : {json{{"mu_t", 8.5}, {"mu_n", 0}}, json{{"drag_rate", 1.96}}}) {
    json bb = b;
    bb.update(fixed);
    try {
      (void)expand({{"base", bb}, {"sweep", {{"lambda", {0.01, 0.1}}}}});
      FAIL() << "a lambda axis beside " << fixed.dump() << " was accepted";
    } catch (const SweepError& e) {
      EXPECT_NE(std::string(e.what()).find("sweep.lambda[0]"), std::string::npos) << e.what();
    }
  }
}

TEST(Sweep, DerivedParametersAndWhereFilters) {
  // fixed zeta * mu = 1 (another parametrisation), keep only w > 3.5
  const auto jobs = expand({{"base", {{"N", 50}, {"W", 12}}},
                            {"sweep", {{"product", {{{"w", {3, 4, 5}}}, {{"lambda", {0.25, 4}}}}}}},
                            {"derived", {{"zeta", "sqrt(lambda)"}, {"mu", "1 / sqrt(lambda)"}}},
                            {"where", {"w > 3.5"}}});
  const std::vector<std::map<std::string, double>> expected = {
      {{"w", 4}, {"zeta", 0.5}, {"mu", 2}}, {{"w", 4}, {"zeta", 2}, {"mu", 0.5}},
      {{"w", 5}, {"zeta", 0.5}, {"mu", 2}}, {{"w", 5}, {"zeta", 2}, {"mu", 0.5}}};
  EXPECT_EQ(table(jobs, {"w", "zeta", "mu"}), expected);
  // derived parameters may use each other
  const auto chained = expand({{"base", {{"N", 50}, {"W", 12}, {"w", 4}}},
                               {"sweep", {{"zeta", {0.5}}}},
                               {"derived", {{"mu", "E_sp / 100 * zeta"}, {"E_sp", "200"}}}});
  EXPECT_DOUBLE_EQ(chained[0].config.mu, 1.0);
  // whole names: E_w = 100 w is not a cycle with w = E_w / 1e3 ... only where a name is used
  const auto words = expand({{"base", {{"N", 50}, {"W", 12}, {"zeta", 0.1}, {"mu", 0.0}}},
                             {"sweep", {{"E_sp", {100}}}},
                             {"derived", {{"w", "E_sp / 25"}, {"E_w", "1e3 * E_sp"}}}});
  EXPECT_DOUBLE_EQ(words[0].config.w, 4.0);
  EXPECT_DOUBLE_EQ(words[0].config.E_w, 1e5);
}

TEST(Sweep, SelfReferenceNanFiltersAndEmptySweepsAreErrors) {
  auto error_of = [](const json& j) -> std::string {
    try {
      (void)Sweep::parse(j, "t").expand();
    } catch (const SweepError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  const json base = {{"N", 50}, {"W", 12}, {"w", 4}, {"zeta", 0.1}, {"mu", 0.0}};
  EXPECT_NE(error_of({{"base", base}, {"sweep", {{"E_sp", {100}}}}, {"derived", {{"E_w", "2 * E_w"}}}}).find("refers to itself"),
            std::string::npos);
  EXPECT_NE(error_of({{"base", base}, {"sweep", {{"E_sp", {100}}}}, {"where", {"sqrt(-E_sp)"}}}).find("NaN"), std::string::npos);
  EXPECT_NE(error_of({{"base", base}, {"sweep", {{"E_sp", {100}}}}, {"where", {"E_sp > 1e9"}}}).find("no jobs"),
            std::string::npos);
}

TEST(Sweep, ReplicasGiveDistinctSeedsAndKeys) {
  const auto jobs = expand({{"base", base()}, {"sweep", {{"w", {3, 4}}}}, {"replicas", 3}});
  ASSERT_EQ(jobs.size(), 6u);
  std::set<std::uint64_t> seeds;
  std::set<std::string> keys;
  for (const auto& j : jobs) {
    seeds.insert(j.config.effective_seed());
    keys.insert(j.key);
  }
  EXPECT_EQ(seeds.size(), 6u);
  EXPECT_EQ(keys.size(), 6u);
  EXPECT_EQ(jobs[2].config.replica, 2);
  EXPECT_EQ(jobs[3].config.w, 4);
}

TEST(Sweep, JobKeysAreStableGoldenValues) {
  // If this fails, every campaign database's job keys have changed: a result would be
  // recomputed instead of found. Change the engine version instead of silently changing keys.
  const auto jobs = expand({{"base", {{"N", 400}, {"W", 25}, {"E_sp", 100}}},
                            {"sweep", {{"product", {{{"lambda", {0, "inf"}}}, {{"w", {3, 8}}}}}}}});
  EXPECT_EQ(jobs[0].key.size(), 64u);
  EXPECT_EQ(std::string(BEVERLOO_VERSION), "0.6.3");
  EXPECT_EQ(jobs[0].key, "58015045e284f1652e51c873c88e1e8707728125f5d110be410ab15e942b9952");
}

TEST(Sweep, KeyIsSensitiveToEveryParameterButNotToRunBookkeeping) {
  const json b = {{"N", 50}, {"W", 12}, {"w", 4}, {"zeta", 0.3}, {"mu", 1.0}};
  const std::string k0 = expand({{"base", b}})[0].key;
  for (const auto& [name, value] : std::vector<std::pair<std::string, json>>{
           {"N", 52}, {"W", 13}, {"w", 4.000000001}, {"zeta", 0.31}, {"mu", 1.01}, {"E_sp", 101}, {"E_w", 9999},
           {"theta_w_deg", 60}, {"size_ratio", 1.3}, {"gravity", 0.5}, {"replica", 1}, {"seed", 5}, {"dt", 1e-4},
           {"dimension", 3}, {"initial_packing_fraction", 0.4}}) {
    json j = b;
    j[name] = value;
    if (name == "dimension") j["W"] = 10;
    EXPECT_NE(expand({{"base", j}})[0].key, k0) << name;
  }
  json run = b;
  run["run"] = {{"t_max", 100}};
  EXPECT_NE(expand({{"base", run}})[0].key, k0) << "t_max changes the result";
  json book = b;
  book["run"] = {{"checkpoint_interval", 7}, {"trajectory_every_steps", 100}};
  book["skin"] = 0.5;
  EXPECT_EQ(expand({{"base", book}})[0].key, k0) << "bookkeeping must not change the job's identity";
}

TEST(Sweep, ExpandingTenThousandJobsIsFast) {
  const json j = {{"base", {{"N", 50}, {"W", 12}}},
                  {"sweep", {{"product", {{{"w", {{"linspace", {2, 10, 100}}}}}, {{"lambda", {{"logspace", {-3, 2, 100}}}}}}}}}};
  const auto t0 = std::chrono::steady_clock::now();
  const auto jobs = expand(j);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(jobs.size(), 10000u);
  std::printf("expanded 10000 jobs in %.3f s\n", s);  // a number for the notes, not a timed assertion
}

}  // namespace
}  // namespace beverloo
