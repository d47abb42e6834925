// Job files: defaults, errors that name the field, the time-step rule, seeds.
#include <gtest/gtest.h>

#include "engine/config.h"
#include "engine/models/model_time_step.h"

namespace beverloo {
namespace {
using nlohmann::json;

json minimal() { return {{"w", 6}, {"zeta", 0.3}, {"mu", 0}}; }

std::string field_of_error(const json& j) {
  try {
    (void)choose_time_step(SimConfig::from_json(j));
  } catch (const ConfigError& e) {
    return e.field();
  }
  return "(accepted)";
}

TEST(Config, DefaultsFollowPhysicsSpec) {
  const SimConfig c = SimConfig::from_json(minimal());
  EXPECT_EQ(c.dimension, 2);
  EXPECT_EQ(c.N, 1600);
  EXPECT_DOUBLE_EQ(c.W, 50);
  EXPECT_DOUBLE_EQ(c.E_w, 1e4);
  EXPECT_DOUBLE_EQ(c.size_ratio, 1.4);
  EXPECT_DOUBLE_EQ(c.theta_w_left_deg, 90);
  EXPECT_DOUBLE_EQ(c.run.t_clog, 100);
  EXPECT_DOUBLE_EQ(c.fire.alpha0, 0.1);
  EXPECT_DOUBLE_EQ(c.fire.f_inc, 1.1);
  EXPECT_DOUBLE_EQ(c.fire.f_dec, 0.5);
  EXPECT_DOUBLE_EQ(c.fire.f_alpha, 0.99);
  EXPECT_EQ(c.fire.n_min, 5);
  EXPECT_DOUBLE_EQ(c.fire.dt_max_factor, 10);
  EXPECT_DOUBLE_EQ(c.sigma_small(), 1 / 1.2);
  EXPECT_DOUBLE_EQ(c.sigma_large(), 1.4 / 1.2);
  json j3 = minimal();
  j3["dimension"] = 3;
  const SimConfig c3 = SimConfig::from_json(j3);
  EXPECT_EQ(c3.N, 6400);
  EXPECT_DOUBLE_EQ(c3.W, 25);
}

TEST(Config, ErrorsNameTheField) {
  struct Case {
    json patch;
    std::string field;
  };
  const std::vector<Case> cases = {
      {{{"w", -1}}, "w"},
      {{{"w", 0}}, "w"},
      {{{"w", 60}}, "w"},
      {{{"w", "six"}}, "w"},
      {{{"zeta", -0.1}}, "zeta"},
      {{{"mu", nullptr}}, "mu"},
      {{{"E_sp", 0}}, "E_sp"},
      {{{"dimension", 4}}, "dimension"},
      {{{"N", 1}}, "N"},
      {{{"N", 10.5}}, "N"},
      {{{"theta_w_deg", 95}}, "theta_w_left_deg"},
      {{{"theta_w_left_deg", -5}}, "theta_w_left_deg"},
      {{{"model", "dpm"}}, "model"},
      {{{"model", "dp_smooth"}, {"dimension", 3}}, "dimension"},
      {{{"model", "dp_smooth"}, {"E_sp", 100}}, "E_sp"},
      {{{"dp", {{"K_l", 10}}}}, "dp"},
      {{{"model", "dp_rough"}, {"dp", {{"K_l", 0}}}}, "dp.K_l"},
      {{{"model", "dp_rough"}, {"dp", {{"Kl", 1}}}}, "dp.Kl"},
      {{{"dt", "fast"}}, "dt"},
      {{{"dt", 0.05}}, "dt"},
      {{{"seed", -3}}, "seed"},
      {{{"typo_field", 1}}, "typo_field"},
      {{{"run", {{"t_max", -5}}}}, "run.t_max"},
      {{{"run", {{"target_rel_err", 2}}}}, "run.target_rel_err"},
      {{{"run", {{"tmax", 5}}}}, "run.tmax"},
      {{{"fire", {{"f_dec", 1.5}}}}, "fire.f_dec"},
      {{{"observables", {{"profile_dh", 0}}}}, "observables.profile_dh"},
      {{{"reinjection", {{"max_attempts", 0}}}}, "reinjection.max_attempts"},
      {{{"max_overlap", 1.5}}, "max_overlap"},
  };
  for (const Case& k : cases) {
    json j = minimal();
    j.merge_patch(k.patch);
    if (k.patch.contains("mu") && k.patch["mu"].is_null()) j.erase("mu");
    EXPECT_EQ(field_of_error(j), k.field) << k.patch.dump();
  }
  json no_w = minimal();
  no_w.erase("w");
  EXPECT_EQ(field_of_error(no_w), "w");
  EXPECT_EQ(field_of_error(json::array()), "(top level)");
}

TEST(Config, ExplicitDtAboveStiffestTermIsRefusedWithTheTermAndTheLimit) {
  json j = minimal();
  j["E_sp"] = 1e5;
  j["dt"] = 1e-3;  // the paper's SP settings are accepted as given ...
  EXPECT_NO_THROW((void)choose_time_step(SimConfig::from_json(j)));
  j["dt"] = 2e-3;  // ... twice that is not
  try {
    (void)choose_time_step(SimConfig::from_json(j));
    FAIL();
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.field(), "dt");
    EXPECT_NE(m.find("E_sp"), std::string::npos) << m;
    EXPECT_NE(m.find("largest accepted dt"), std::string::npos) << m;
  }
}

TEST(Config, AutoTimeStepFollowsTheStiffestTerm) {
  json j = minimal();
  j["E_sp"] = 100;
  TimeStepChoice t = choose_time_step(SimConfig::from_json(j));
  EXPECT_DOUBLE_EQ(t.dt, 1e-3);  // soft particles: the paper's dt
  j["E_sp"] = 1e5;
  t = choose_time_step(SimConfig::from_json(j));
  // physics.md 5: SP at E_sp = 1e5 has T ~ 9e-3 from the small-small reduced mass
  EXPECT_NEAR(t.period_min, 8.65e-3, 0.1e-3);
  EXPECT_NEAR(t.dt, t.period_min / 15, 1e-12);
  EXPECT_NE(t.period_term.find("E_sp"), std::string::npos);
  EXPECT_EQ(t.limiting_term, t.period_term);
}

TEST(Config, TheLimitingTermIsTheBoundThatSetsDt) {
  // soft disks: the 1e-3 cap; strong friction: its damping time, not the contact's period
  json j = minimal();
  j["E_sp"] = 100;
  j["mu"] = 0;
  EXPECT_EQ(choose_time_step(SimConfig::from_json(j)).limiting_term, "the largest dt, 1e-3");
  j["mu"] = 200;
  const TimeStepChoice t = choose_time_step(SimConfig::from_json(j));
  ASSERT_LT(t.tau_min / 5, t.period_min / 15);
  EXPECT_NEAR(t.dt, t.tau_min / 5, 1e-15);
  EXPECT_EQ(t.limiting_term, t.tau_term);
  EXPECT_NE(t.limiting_term.find("mu"), std::string::npos) << t.limiting_term;
}

TEST(Config, CanonicalJsonRoundTripsAndSeedDependsOnPhysicsOnly) {
  const SimConfig a = SimConfig::from_json(minimal());
  const SimConfig b = SimConfig::from_json(a.to_json());
  EXPECT_EQ(a.to_json().dump(), b.to_json().dump());
  EXPECT_EQ(a.effective_seed(), b.effective_seed());
  json longer = minimal();
  longer["run"] = {{"t_max", 5000}, {"checkpoint_interval", 7}};
  EXPECT_EQ(SimConfig::from_json(longer).effective_seed(), a.effective_seed()) << "run controls must not change the trajectory";
  json numerics = minimal();
  numerics["skin"] = 0.5;
  numerics["max_overlap"] = 0.7;
  EXPECT_EQ(SimConfig::from_json(numerics).effective_seed(), a.effective_seed()) << "numerical settings must not change the trajectory";
  for (const auto& [key, value] : std::vector<std::pair<std::string, json>>{
           {"w", 6.5}, {"zeta", 0.31}, {"mu", 1e-9}, {"E_sp", 101}, {"replica", 1}, {"N", 1601}, {"theta_w_deg", 60}}) {
    json j = minimal();
    j[key] = value;
    EXPECT_NE(SimConfig::from_json(j).effective_seed(), a.effective_seed()) << key;
  }
  json explicit_seed = minimal();
  explicit_seed["seed"] = 42;
  EXPECT_EQ(SimConfig::from_json(explicit_seed).effective_seed(), 42u);
}

}  // namespace
}  // namespace beverloo
