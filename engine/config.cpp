#include "config.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

#include "parameters.h"
#include "rng.h"
#include "units.h"

namespace beverloo {
namespace {

using nlohmann::json;

void require(bool ok, const std::string& field, const std::string& reason) {
  if (!ok) throw ConfigError(field, reason);
}
std::string num(double x) { return json(x).dump(); }

/// x with 4 significant digits, for messages.
std::string short_num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}

/// The tallest funnel wall (sigma_avg) a 2D container may have.
constexpr double kMaxFunnelHeight = 1e4;

}  // namespace

namespace {

bool applies(ParamModels m, const std::string& model) { return parameter_applies(m, model); }
std::string models_text(ParamModels m) {
  switch (m) {
    case ParamModels::Sp: return "the model \"sp\"";
    case ParamModels::Dp: return "the models \"dp_smooth\" and \"dp_rough\"";
    case ParamModels::DpSmooth: return "the model \"dp_smooth\"";
    default: return "every model";
  }
}
/// Splits "dp.K_l" into ("dp", "K_l"); "E_sp" into ("", "E_sp").
std::pair<std::string, std::string> split_path(std::string_view path) {
  const auto dot = path.find('.');
  if (dot == std::string_view::npos) return {"", std::string(path)};
  return {std::string(path.substr(0, dot)), std::string(path.substr(dot + 1))};
}

std::string show_value(const ParamSpec& p, SimConfig& c) {
  const ParamAccess& a = p.access;
  if (a.real) return num(a.real(c));
  if (a.integer) return std::to_string(a.integer(c));
  if (a.integer64) return std::to_string(a.integer64(c));
  if (a.optional_real) return a.optional_real(c) ? num(*a.optional_real(c)) : "unset";
  return "";
}

bool in_range(const ParamSpec& p, double x) {
  if (p.has_lo() && (p.lo_open ? !(x > p.lo) : !(x >= p.lo))) return false;
  if (p.has_hi() && (p.hi_open ? !(x < p.hi) : !(x <= p.hi))) return false;
  return true;
}

/// The value of a numeric row as a double (nullopt: unset optional, or not numeric).
std::optional<double> numeric_value(const ParamSpec& p, SimConfig& c) {
  const ParamAccess& a = p.access;
  if (a.real) return a.real(c);
  if (a.integer) return a.integer(c);
  if (a.integer64) return static_cast<double>(a.integer64(c));
  if (a.optional_real && a.optional_real(c)) return *a.optional_real(c);
  return std::nullopt;
}

void check_range(const ParamSpec& p, SimConfig& c) {
  const std::optional<double> x = numeric_value(p, c);
  if (x && !in_range(p, *x)) throw ConfigError(std::string(p.path), p.rule_text() + ", got " + show_value(p, c));
}

/// An integer JSON value, range-checked before it is narrowed (so that 4294967336 is not 40).
std::int64_t read_integer(const ParamSpec& p, const json& v, const std::string& field) {
  double d;
  if (v.is_number_unsigned()) {
    if (v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)) throw ConfigError(field, "is too large, got " + v.dump());
    d = static_cast<double>(v.get<std::int64_t>());
  } else if (v.is_number_integer()) {
    d = static_cast<double>(v.get<std::int64_t>());
  } else if (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>() && std::fabs(v.get<double>()) < 9e15) {
    d = v.get<double>();
  } else {
    throw ConfigError(field, "must be an integer, got " + v.dump());
  }
  const double limit = p.type == ParamType::Integer ? 2147483647.0 : 9.2e18;
  if (std::fabs(d) > limit || !in_range(p, d))
    throw ConfigError(field, (p.rule_text().empty() ? "is out of range" : p.rule_text()) + ", got " + v.dump());
  return v.is_number_float() ? static_cast<std::int64_t>(d) : v.get<std::int64_t>();
}

/// Reads one row's value from the JSON into the config; range-checks explicit values at once
/// (so that an explicit 0 is never taken for "use the default").
void read_value(const ParamSpec& p, const json& v, SimConfig& c) {
  const std::string field(p.path);
  const ParamAccess& a = p.access;
  switch (p.type) {
    case ParamType::Real:
    case ParamType::OptionalReal: {
      if (!v.is_number()) throw ConfigError(field, "must be a number, got " + v.dump());
      const double x = v.get<double>();
      if (!std::isfinite(x)) throw ConfigError(field, "must be finite");
      if (a.real) a.real(c) = x; else a.optional_real(c) = x;
      break;
    }
    case ParamType::Integer:
      a.integer(c) = static_cast<int>(read_integer(p, v, field));
      break;
    case ParamType::Integer64:
      a.integer64(c) = read_integer(p, v, field);
      break;
    case ParamType::Boolean:
      if (!v.is_boolean()) throw ConfigError(field, "must be true or false, got " + v.dump());
      a.boolean(c) = v.get<bool>();
      break;
    case ParamType::Text:
      if (!v.is_string()) throw ConfigError(field, "must be a string, got " + v.dump());
      a.text(c) = v.get<std::string>();
      break;
    case ParamType::RealOrAuto:
      if (v.is_string()) {
        if (v.get<std::string>() != "auto") throw ConfigError(field, "must be a number or \"auto\", got " + v.dump());
        a.optional_real(c).reset();
      } else if (v.is_number() && std::isfinite(v.get<double>())) {
        a.optional_real(c) = v.get<double>();
      } else {
        throw ConfigError(field, "must be a number or \"auto\", got " + v.dump());
      }
      break;
    case ParamType::Seed:
      if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0))
        throw ConfigError(field, "must be a non-negative integer, got " + v.dump());
      a.seed(c) = v.get<std::uint64_t>();
      break;
  }
  if (p.type != ParamType::Text && p.type != ParamType::Boolean && p.type != ParamType::Seed) check_range(p, c);
}

}  // namespace

SimConfig SimConfig::from_json(const json& j) {
  SimConfig c;
  if (!j.is_object()) throw ConfigError("(top level)", "must be a JSON object");
  // the model first: which rows apply depends on it
  if (j.contains("model")) read_value(*find_parameter("model"), j.at("model"), c);
  std::set<std::string> known_top = {"comment"};
  std::set<std::string> groups;
  for (const ParamSpec& p : job_parameters()) {
    const auto [g, k] = split_path(p.path);
    known_top.insert(g.empty() ? k : g);
    if (!g.empty()) groups.insert(g);
  }
  for (const std::string& g : groups) {
    if (!j.contains(g)) continue;
    if (!j.at(g).is_object()) throw ConfigError(g, "must be a JSON object");
    if (g == "dp" && !c.is_dp())
      throw ConfigError("dp", "applies to the models \"dp_smooth\" and \"dp_rough\" only, not \"" + c.model + "\"");
  }
  if (j.contains("theta_w_deg") && (j.contains("theta_w_left_deg") || j.contains("theta_w_right_deg")))
    throw ConfigError("theta_w_deg", "give either theta_w_deg or theta_w_left_deg/theta_w_right_deg, not both");
  for (const ParamSpec& p : job_parameters()) {
    const auto [g, k] = split_path(p.path);
    const json* v = nullptr;
    if (g.empty() ? j.contains(k) : (j.contains(g) && j.at(g).contains(k))) v = g.empty() ? &j.at(k) : &j.at(g).at(k);
    if (!v) continue;
    if (p.path == "model") continue;
    if (!applies(p.models, c.model)) {
      std::string hint = p.path == "E_sp" ? "; the DP contact stiffness is dp.E_c" : "";
      throw ConfigError(std::string(p.path), "applies to " + models_text(p.models) + " only, not \"" + c.model + "\"" + hint);
    }
    if (p.path == "theta_w_deg") {  // the shorthand sets both sides (their rows check the range)
      if (!v->is_number()) throw ConfigError("theta_w_deg", "must be a number, got " + v->dump());
      c.theta_w_left_deg = c.theta_w_right_deg = v->get<double>();
      continue;
    }
    read_value(p, *v, c);
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!known_top.count(it.key())) throw ConfigError(it.key(), "unknown field");
    if (!groups.count(it.key())) continue;
    for (auto f = it.value().begin(); f != it.value().end(); ++f)
      if (!find_parameter(it.key() + "." + f.key())) throw ConfigError(it.key() + "." + f.key(), "unknown field");
  }
  if (j.contains("comment") && !j.at("comment").is_string())  // free text for people; not part of the job
    throw ConfigError("comment", "must be a string, got " + j.at("comment").dump());
  for (const ParamSpec& p : job_parameters())
    if (p.required && !j.contains(std::string(p.path))) throw ConfigError(std::string(p.path), "is required: " + std::string(p.doc));
  c.resolve_and_validate();
  return c;
}

void SimConfig::resolve_and_validate() {
  require(model == "sp" || is_dp(), "model",
          "\"" + model + "\" is not a known model (known: \"sp\", \"dp_smooth\", \"dp_rough\")");
  require(dimension == 2 || dimension == 3, "dimension", "must be 2 or 3, got " + std::to_string(dimension));
  if (is_dp())
    require(dimension == 2, "dimension", "the DP models are 2D only (physics.md 4), got " + std::to_string(dimension));
  // dimension- and model-dependent defaults (0 or -1 mark "not given" in a programmatic config)
  if (skin == 0) skin = is_dp() ? 0.1 : 0.3;
  if (N == 0) N = dimension == 2 ? 1600 : 6400;
  if (W == 0) W = dimension == 2 ? 50.0 : 25.0;
  require(w != 0, "w", "is required (orifice width in sigma_avg)");
  require(zeta != -1, "zeta", "is required (viscous drag; 0 for friction only)");
  require(mu != -1, "mu", "is required (kinetic friction; 0 for drag only)");
  // a split equal to mu is no split: the canonical job (and its key) does not carry it
  if (mu_n && *mu_n == mu) mu_n.reset();
  if (mu_t && *mu_t == mu) mu_t.reset();
  for (const ParamSpec& p : job_parameters()) {
    if (!applies(p.models, model) || p.path == "theta_w_deg") continue;
    check_range(p, *this);
    if (p.type == ParamType::Text && !p.allowed.empty() && p.path != "model") {
      const std::string v = p.access.text(*this), all = "," + std::string(p.allowed) + ",";
      if (all.find("," + v + ",") == std::string::npos)
        throw ConfigError(std::string(p.path), "\"" + v + "\" is not one of " + std::string(p.allowed));
    }
  }
  // rules that relate two fields
  require(w < W, "w", "must be smaller than the container width W = " + num(W) + ", got " + num(w));
  require(drain.stop_below < N, "drain.stop_below", "must be smaller than N = " + std::to_string(N));
  if (!reinject) {
    require(run.trajectory_every_steps == 0, "run.trajectory_every_steps",
            "a draining hopper writes no trajectory: particles leave it, and the H5MD frames hold a fixed number");
    // the fit of dN/dt = -c0 sqrt(N) needs 3 blocks between the skipped ends (drain_fit.h)
    const int steady = N - std::max(drain.stop_below, drain.fit_skip) - drain.fit_skip;
    require(steady > 3 * drain.block_exits, "drain.fit_skip",
            "a draining hopper of N = " + std::to_string(N) + " leaves " + std::to_string(std::max(steady, 0)) +
                " steady exits after leaving out " + std::to_string(drain.fit_skip) + " at each end (and stopping at " +
                std::to_string(drain.stop_below) + "); the fit needs more than 3 drain.block_exits = " +
                std::to_string(3 * drain.block_exits) + ": raise N or lower drain.fit_skip");
  }
  require(theta_w_left_deg > 0 || theta_w_right_deg > 0, "theta_w_deg",
          "at most one funnel wall may be vertical (0 degrees); both are 0, which leaves no floor");
  // a funnel wall almost vertical but not quite rises (W - w)/2 / tan(theta) (all of W - w when
  // the other wall is vertical): beyond kMaxFunnelHeight the container is no longer one the
  // neighbour list's grid and the placement can hold; 0 is the vertical wall
  if (dimension == 2)
    for (const auto& [field, theta, other] : {std::tuple{"theta_w_left_deg", theta_w_left_deg, theta_w_right_deg},
                                              std::tuple{"theta_w_right_deg", theta_w_right_deg, theta_w_left_deg}}) {
      if (!(theta > 0 && theta < 90)) continue;
      const double run = other == 0 ? W - w : 0.5 * (W - w);
      const double rad = theta * units::pi / 180, height = run * std::cos(rad) / std::sin(rad);
      require(height <= kMaxFunnelHeight, field,
              short_num(theta) + " degrees makes the funnel wall rise " + short_num(height) + " sigma_avg; at most " +
                  short_num(kMaxFunnelHeight) + " (a vertical wall is 0 degrees)");
    }
  // A setting that cannot change a result must not change a job's key or seed: the draining
  // hopper's fit and stop on a continuous flow, the reinjection's choice on a drain (which
  // reinjects nothing; its drop depth still says when a particle is taken out) are refused,
  // as DP options on an SP job are
  {
    const SimConfig d;
    const std::tuple<const char*, bool, bool> unused[] = {
        // field, at its default, whether it can matter (a drain's fit and stop; a flow's reinjection)
        {"drain.stop_below", drain.stop_below == d.drain.stop_below, !reinject},
        {"drain.fit_skip", drain.fit_skip == d.drain.fit_skip, !reinject},
        {"drain.block_exits", drain.block_exits == d.drain.block_exits, !reinject},
        {"reinjection.rule", reinjection.rule == d.reinjection.rule, reinject},
        {"reinjection.top_band", reinjection.top_band == d.reinjection.top_band, reinject},
        {"reinjection.max_attempts", reinjection.max_attempts == d.reinjection.max_attempts, reinject},
    };
    for (const auto& [field, at_default, matters] : unused)
      require(at_default || matters, field,
              reinject ? "applies to a draining hopper (reinject = false) only: a continuous flow's result does not depend on it"
                       : "a draining hopper (reinject = false) reinjects nothing: it would change no result");
  }
  // the container must hold a particle: W above the large particles' diameter
  {
    const double sigma_large = 2 * size_ratio / (1 + size_ratio);
    require(W > sigma_large, "W", short_num(W) + " is narrower than a large particle (diameter " + short_num(sigma_large) +
                                      " sigma_avg): no particle fits the container");
  }
  if (dimension == 3)
    require(theta_w_left_deg == 90 && theta_w_right_deg == 90, "theta_w_deg",
            "the 3D hopper has a flat base only (90 degrees), got " + num(theta_w_left_deg));
  if (reinjection.rule == "lanes")
    require(dimension == 2, "reinjection.rule", "\"lanes\" is the authors' 2D rule; 3D jobs use \"pile\"");
  require(run.rate_bin <= run.min_window / 8, "run.rate_bin", "must be at most run.min_window / 8 (block averaging needs bins)");
  require(observables.block_length >= observables.sample_interval, "observables.block_length",
          "must be >= observables.sample_interval");
  require(observables.profile_h_max > observables.profile_dh, "observables.profile_h_max", "must be > observables.profile_dh");
}

nlohmann::json SimConfig::to_json() const {
  SimConfig& self = const_cast<SimConfig&>(*this);  // the accessors are shared with the reader
  SimConfig defaults;
  json j = json::object();
  for (const ParamSpec& p : job_parameters()) {
    const ParamAccess& a = p.access;
    if (!applies(p.models, model) || p.path == "theta_w_deg") continue;
    // rows added after 0.2.0 are left out at their default (before their group is made, so that
    // no empty group enters the canonical job either)
    if (p.omit_at_default &&
        ((p.type == ParamType::Real && a.real(self) == a.real(defaults)) ||
         (p.type == ParamType::Integer && a.integer(self) == a.integer(defaults)) ||
         (p.type == ParamType::Boolean && a.boolean(self) == a.boolean(defaults)) ||
         (p.type == ParamType::Text && a.text(self) == a.text(defaults))))
      continue;
    const auto [g, k] = split_path(p.path);
    json& obj = g.empty() ? j : j[g];
    switch (p.type) {
      case ParamType::Real:
        obj[k] = a.real(self);
        break;
      case ParamType::OptionalReal:
        if (!a.optional_real(self)) continue;
        obj[k] = *a.optional_real(self);
        break;
      case ParamType::Integer: obj[k] = a.integer(self); break;
      case ParamType::Integer64: obj[k] = a.integer64(self); break;
      case ParamType::Boolean: obj[k] = a.boolean(self); break;
      case ParamType::Text:
        obj[k] = a.text(self);
        break;
      case ParamType::RealOrAuto:
        if (a.optional_real(self)) obj[k] = *a.optional_real(self); else obj[k] = "auto";
        break;
      case ParamType::Seed:
        if (!a.seed(self)) continue;
        obj[k] = *a.seed(self);
        break;
    }
  }
  return j;
}

namespace {
/// Removes the rows whose flag is false (or, with drop_when_set, true) from a canonical job, and
/// groups left empty.
void erase_rows(json& j, bool ParamSpec::*keep, bool drop_when_set = false) {
  for (const ParamSpec& p : job_parameters()) {
    if (p.*keep != drop_when_set) continue;
    const auto [g, k] = split_path(p.path);
    if (g.empty()) {
      j.erase(k);
    } else if (j.contains(g)) {
      j[g].erase(k);
      if (j[g].empty()) j.erase(g);
    }
  }
}
}  // namespace

nlohmann::json SimConfig::key_json() const {
  json j = to_json();
  erase_rows(j, &ParamSpec::in_key);
  return j;
}

nlohmann::json SimConfig::trajectory_json() const {
  json j = to_json();
  erase_rows(j, &ParamSpec::stop_rule, true);
  return j;
}

std::uint64_t SimConfig::effective_seed() const {
  if (seed) return *seed;
  // only what defines the trajectory: not the run controls, not the Verlet skin (the force
  // sums do not depend on it), not the blow-up threshold
  json j = to_json();
  erase_rows(j, &ParamSpec::in_seed);
  return hash64(j.dump());
}

}  // namespace beverloo
