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
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace beverloo {

struct LambdaJob {
  std::optional<nlohmann::json> job;  ///< the canonical job of the new series (a's width and replica)
  std::string problem;                ///< why there is none: the two series differ in both, ...
};

/// a, b: canonical jobs of two different series of the group (any order).
LambdaJob job_at_lambda(const nlohmann::json& a, const nlohmann::json& b, double lambda);

/// The series of a beta(lambda) group as the planner places a new lambda among them: the
/// finite ones by lambda, and the limits where the group has them (canonical jobs).
struct LambdaGroupJobs {
  std::vector<std::pair<double, nlohmann::json>> finite;  ///< (lambda, job), lambda ascending, >= 2
  const nlohmann::json* limit0 = nullptr;                 ///< the lambda = 0 series (friction only)
  const nlohmann::json* limit_inf = nullptr;              ///< the lambda = inf series (drag only)
};

/// A new lambda placed between the two series that bracket it. The limits bracket too: beyond
/// the highest finite series the next one up is the lambda = inf series, so when the two share
/// their drag the friction is lowered (the authors' second branch), not the drag raised (a
/// measured Fig. 4a campaign that raised it spent 80 % of its flow on drag rates 2-6 times the
/// grid's, where Q falls as 1/drag); the same below with the lambda = 0 series and the drag.
/// Where the limit shares neither, or there is none, the last two finite series (as before).
/// The job copies the finite series' form (its width and replica; the planner sets both).
LambdaJob job_at_lambda_in_group(const LambdaGroupJobs& group, double lambda);

}  // namespace beverloo
