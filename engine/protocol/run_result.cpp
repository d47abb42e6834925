#include "run_result.h"

#include "result_fields.h"

#include <variant>

namespace beverloo {

nlohmann::json RunResult::flow_summary_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const ResultField& f : result_fields())
    if (f.in_summary) std::visit([&](const auto& v) { j[std::string(f.name)] = v; }, f.get(*this));
  return j;
}

nlohmann::json RunResult::summary_json() const {
  nlohmann::json j = flow_summary_json();
  if (draining)  // only then: a continuous run's summary stays as it was
    j["drain"] = {{"n_initial", n_initial}, {"n_remaining", n_remaining}, {"fit_ok", drain.ok},
                  {"fit_message", drain.message}, {"c0", drain.c0}, {"c0_err", drain.c0_err},
                  {"chi2_red", drain.chi2_red}, {"blocks", drain.blocks}, {"exits_used", drain.exits_used}};
  return j;
}

}  // namespace beverloo
