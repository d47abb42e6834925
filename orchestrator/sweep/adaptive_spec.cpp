#include "adaptive_spec.h"

#include <cmath>
#include <set>
#include <string>

#include "sweep.h"

namespace beverloo {
namespace {
using nlohmann::json;

std::string shown(const json& v) {
  const std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 60) + "..." : s;
}

double positive_number(const json& v, const std::string& path) {
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0)
    throw SweepError(path, shown(v) + ": must be a finite number > 0");
  return v.get<double>();
}

void only_fields(const json& obj, const std::set<std::string>& known, const std::string& path, const char* list) {
  for (auto it = obj.begin(); it != obj.end(); ++it)
    if (!known.count(it.key())) throw SweepError(path + "." + it.key(), std::string("unknown field (known: ") + list + ")");
}
int integer_in(const json& v, const std::string& path, long lo, long hi) {
  if (!v.is_number_integer() || v.get<long>() < lo || v.get<long>() > hi)
    throw SweepError(path, shown(v) + ": must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v.get<long>());
}

LambdaAdaptiveSpec parse_lambda(const json& block) {
  const std::string at = "adaptive.lambda";
  if (!block.is_object()) throw SweepError(at, shown(block) + ": must be an object");
  only_fields(block, {"target", "range", "per_decade", "max_added_series"}, at,
              "target, range, per_decade, max_added_series");
  LambdaAdaptiveSpec s;
  if (!block.contains("target"))
    throw SweepError(at + ".target",
                     "missing: say which errors are wanted (log10_lambda_c_err, b_err, crossing_interpolation_err)");
  const json& t = block["target"];
  if (!t.is_object()) throw SweepError(at + ".target", shown(t) + ": must be an object");
  only_fields(t, {"log10_lambda_c_err", "b_err", "crossing_interpolation_err"}, at + ".target",
              "log10_lambda_c_err, b_err, crossing_interpolation_err");
  if (t.contains("log10_lambda_c_err"))
    s.log10_lambda_c_err = positive_number(t["log10_lambda_c_err"], at + ".target.log10_lambda_c_err");
  if (t.contains("b_err")) s.b_err = positive_number(t["b_err"], at + ".target.b_err");
  if (t.contains("crossing_interpolation_err"))
    s.crossing_interpolation_err =
        positive_number(t["crossing_interpolation_err"], at + ".target.crossing_interpolation_err");
  if (!s.log10_lambda_c_err && !s.b_err && !s.crossing_interpolation_err)
    throw SweepError(at + ".target", "names no target (log10_lambda_c_err, b_err, crossing_interpolation_err)");
  if (!block.contains("range")) throw SweepError(at + ".range", "missing: the lambdas [lo, hi] new series may take");
  const json& r = block["range"];
  if (!r.is_array() || r.size() != 2) throw SweepError(at + ".range", shown(r) + ": must be [lo, hi]");
  s.lambda_lo = positive_number(r[0], at + ".range[0]");
  s.lambda_hi = positive_number(r[1], at + ".range[1]");
  if (!(s.lambda_hi > s.lambda_lo)) throw SweepError(at + ".range", shown(r) + ": hi must be above lo");
  if (block.contains("per_decade")) s.per_decade = integer_in(block["per_decade"], at + ".per_decade", 1, 100);
  if (std::log10(s.lambda_hi / s.lambda_lo) * s.per_decade > 10000)
    throw SweepError(at + ".per_decade", "more than 10000 candidate lambdas in range");
  if (block.contains("max_added_series"))
    s.max_added_series = integer_in(block["max_added_series"], at + ".max_added_series", 1, 1000);
  return s;
}

}  // namespace

AdaptiveSpec AdaptiveSpec::parse(const json& block) {
  if (!block.is_object()) throw SweepError("adaptive", shown(block) + ": must be an object");
  only_fields(block, {"target", "w_range", "w_step", "max_added_jobs", "extend", "lambda", "comment"}, "adaptive",
              "target, w_range, w_step, max_added_jobs, extend, lambda, comment");
  AdaptiveSpec s;
  if (!block.contains("target")) throw SweepError("adaptive.target", "missing: say which errors are wanted (k_err, beta_err)");
  const json& t = block["target"];
  if (!t.is_object()) throw SweepError("adaptive.target", shown(t) + ": must be an object");
  only_fields(t, {"k_err", "beta_err"}, "adaptive.target", "k_err, beta_err");
  if (t.contains("k_err")) s.k_err = positive_number(t["k_err"], "adaptive.target.k_err");
  if (t.contains("beta_err")) s.beta_err = positive_number(t["beta_err"], "adaptive.target.beta_err");
  if (!s.k_err && !s.beta_err) throw SweepError("adaptive.target", "names no target (k_err, beta_err)");
  if (!block.contains("w_range")) throw SweepError("adaptive.w_range", "missing: the widths [lo, hi] new jobs may take");
  const json& r = block["w_range"];
  if (!r.is_array() || r.size() != 2) throw SweepError("adaptive.w_range", shown(r) + ": must be [lo, hi]");
  s.w_lo = positive_number(r[0], "adaptive.w_range[0]");
  s.w_hi = positive_number(r[1], "adaptive.w_range[1]");
  if (!(s.w_hi > s.w_lo)) throw SweepError("adaptive.w_range", shown(r) + ": hi must be above lo");
  if (block.contains("w_step")) s.w_step = positive_number(block["w_step"], "adaptive.w_step");
  if ((s.w_hi - s.w_lo) / s.w_step > 10000)
    throw SweepError("adaptive.w_step", shown(block["w_step"]) + ": more than 10000 candidate widths in w_range");
  if (block.contains("max_added_jobs")) {
    const json& m = block["max_added_jobs"];
    if (!m.is_number_integer() || m.get<long>() < 1 || m.get<long>() > 10000)
      throw SweepError("adaptive.max_added_jobs", shown(m) + ": must be an integer in [1, 10000]");
    s.max_added_jobs = static_cast<int>(m.get<long>());
  }
  if (block.contains("extend")) {
    if (!block["extend"].is_boolean()) throw SweepError("adaptive.extend", shown(block["extend"]) + ": must be true or false");
    s.extend = block["extend"].get<bool>();
  }
  if (block.contains("comment") && !block["comment"].is_string())
    throw SweepError("adaptive.comment", shown(block["comment"]) + ": must be a string");
  if (block.contains("lambda")) s.lambda = parse_lambda(block["lambda"]);
  return s;
}

std::optional<AdaptiveSpec> AdaptiveSpec::of_sweep(const json& sweep) {
  if (!sweep.is_object() || !sweep.contains("adaptive")) return std::nullopt;
  return parse(sweep["adaptive"]);
}

}  // namespace beverloo
