#include "lambda_series.h"

#include <cmath>

#include "engine/config.h"
#include "engine/parameters.h"
#include "number_format.h"

namespace beverloo {

LambdaJob job_at_lambda(const nlohmann::json& a, const nlohmann::json& b, double lambda) {
  LambdaJob out;
  if (!(lambda > 0) || !std::isfinite(lambda)) {
    out.problem = "lambda must be finite and > 0";
    return out;
  }
  const SimConfig ca = SimConfig::from_json(a), cb = SimConfig::from_json(b);
  const double drag_a = derived::drag_coefficient(ca), drag_b = derived::drag_coefficient(cb);
  const double fric_a = derived::friction_coefficient(ca), fric_b = derived::friction_coefficient(cb);
  nlohmann::json job = a;
  if (drag_a == drag_b && drag_a > 0) {  // the friction varies: mu (or mu_t of a split) = drag / lambda
    job[a.contains("mu_t") ? "mu_t" : "mu"] = drag_a / lambda;
  } else if (fric_a == fric_b && fric_a > 0) {  // the drag varies: drag = lambda friction
    const double drag = lambda * fric_a;
    if (ca.drag_rate > 0 && ca.zeta == 0)
      job["drag_rate"] = drag / derived::mean_particle_mass(ca.dimension);
    else if (ca.drag_rate == 0)
      job["zeta"] = drag;
    else {
      out.problem = "the series have drag both as zeta and as a rate";
      return out;
    }
  } else {
    out.problem = "the two nearest series (lambda " + format_value(derived::lambda(ca).value_or(NAN), 4) + " and " +
                  format_value(derived::lambda(cb).value_or(NAN), 4) +
                  ") differ in both drag and friction: no axis to place lambda on";
    return out;
  }
  SimConfig c = SimConfig::from_json(job);
  c.resolve_and_validate();
  const std::optional<double> got = derived::lambda(c);
  if (!got || std::fabs(*got / lambda - 1) > 1e-9) {
    out.problem = "the job made for lambda = " + format_value(lambda, 4) + " has lambda " + format_value(got.value_or(NAN), 6);
    return out;
  }
  out.job = c.to_json();
  return out;
}

LambdaJob job_at_lambda_in_group(const LambdaGroupJobs& group, double lambda) {
  const auto& f = group.finite;
  if (f.size() < 2) return LambdaJob{std::nullopt, "the group needs two finite series to place a lambda"};
  std::size_t hi = 0;
  while (hi < f.size() && f[hi].first < lambda) ++hi;
  if (hi == f.size() && group.limit_inf) {  // above every finite series: towards lambda = inf
    LambdaJob made = job_at_lambda(f.back().second, *group.limit_inf, lambda);
    if (made.job) return made;
  }
  if (hi == 0 && group.limit0) {  // below every finite series: towards lambda = 0
    LambdaJob made = job_at_lambda(f.front().second, *group.limit0, lambda);
    if (made.job) return made;
  }
  const std::size_t a = hi == 0 ? 0 : hi == f.size() ? f.size() - 2 : hi - 1;
  return job_at_lambda(f[a].second, f[a + 1].second, lambda);
}

}  // namespace beverloo
