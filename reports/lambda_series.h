#pragma once
/// \file lambda_series.h
/// \brief How the adaptive planner realises a new lambda in a beta(lambda) group: from the two
/// series nearest to it (bracketing it, or the last two beyond either end), keep the dissipation
/// they share and set the other so that lambda = drag / friction (derived::lambda) is the new
/// value. That follows both lambda axes of the paper without knowing them: the text's axis
/// (fixed drag zeta = s/sqrt 10, friction mu = zeta/lambda) and the authors' two branches (drag
/// rate varied at a fixed friction, then friction varied at a fixed drag). The drag is set as
/// the series give it (a rate times the mass, or zeta); a friction split keeps mu_n and sets mu_t.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace beverloo {

struct LambdaJob {
  std::optional<nlohmann::json> job;  ///< the canonical job of the new series (a's width and replica)
  std::string problem;                ///< why there is none: the two series differ in both, ...
};

/// a, b: canonical jobs of two different series of the group (any order).
LambdaJob job_at_lambda(const nlohmann::json& a, const nlohmann::json& b, double lambda);

}  // namespace beverloo
