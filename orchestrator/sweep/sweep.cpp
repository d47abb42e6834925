#include <algorithm>
#include "sweep.h"

#include "adaptive_spec.h"

#include "engine/models/model_time_step.h"
#include "core/digest.h"
#include "engine/json_file.h"
#include "engine/parameters.h"
#include "core/version.h"


#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <muParser.h>
#include <set>

namespace beverloo {
namespace {
using nlohmann::json;

/// A value with the JSON path it came from, so that an engine error can name it.
struct Tagged {
  json value;
  std::string path;
};
using Point = std::map<std::string, Tagged>;

/// The sweepable rows of the parameter table, and the sweep's own labels lambda and
/// dissipation_scale (they set zeta and mu, docs/sweeps.md).
const std::set<std::string>& sweepable() {
  static const std::set<std::string> names = [] {
    std::set<std::string> n = {"lambda", "dissipation_scale"};
    for (const ParamSpec& p : job_parameters())
      if (p.sweepable) n.insert(std::string(p.path));
    return n;
  }();
  return names;
}
std::string known_list() {
  std::string s;
  for (const auto& n : sweepable()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string show(const json& v) { return v.dump(); }

std::vector<Tagged> values_of(const json& spec, const std::string& path) {
  std::vector<Tagged> out;
  auto check_count = [&](const json& a, const std::string& p) {
    if (!a.is_array() || a.size() != 3 || !a[0].is_number() || !a[1].is_number() || !a[2].is_number_integer())
      throw SweepError(p, show(a) + ": must be [start, stop, count] with an integer count");
    if (a[2].get<long>() < 1) throw SweepError(p + "[2]", show(a[2]) + ": count must be >= 1");
    if (a[2].get<long>() > 1000000) throw SweepError(p + "[2]", show(a[2]) + ": count must be <= 1e6");
  };
  if (spec.is_array()) {
    if (spec.empty()) throw SweepError(path, "[]: a list of values must not be empty");
    for (std::size_t k = 0; k < spec.size(); ++k) {
      if (spec[k].is_object() || spec[k].is_array() || spec[k].is_null())
        throw SweepError(path + "[" + std::to_string(k) + "]", show(spec[k]) + ": must be a number, string or boolean");
      out.push_back({spec[k], path + "[" + std::to_string(k) + "]"});
    }
    return out;
  }
  if (spec.is_object()) {
    if (spec.size() != 1)
      throw SweepError(path, show(spec) + ": a range has exactly one of values, linspace, logspace, geomspace");
    const std::string kind = spec.begin().key();
    const json& a = spec.begin().value();
    const std::string p = path + "." + kind;
    if (kind == "values") return values_of(a, p);
    if (kind != "linspace" && kind != "logspace" && kind != "geomspace")
      throw SweepError(p, "unknown range kind (known: values, linspace, logspace, geomspace)");
    check_count(a, p);
    const double lo = a[0].get<double>(), hi = a[1].get<double>();
    const long n = a[2].get<long>();
    if (kind == "geomspace" && (lo <= 0 || hi <= 0)) throw SweepError(p, show(a) + ": geomspace needs positive ends");
    for (long k = 0; k < n; ++k) {
      const double f = n == 1 ? 0.0 : static_cast<double>(k) / (n - 1);
      double v;
      if (kind == "linspace")
        v = lo + f * (hi - lo);
      else if (kind == "logspace")
        v = std::pow(10.0, lo + f * (hi - lo));
      else
        v = std::exp(std::log(lo) + f * (std::log(hi) - std::log(lo)));
      if (k == n - 1) v = kind == "linspace" ? hi : (kind == "logspace" ? std::pow(10.0, hi) : hi);  // exact ends
      out.push_back({v, p + "[" + std::to_string(k) + "]"});
    }
    return out;
  }
  if (spec.is_null()) throw SweepError(path, "null: must be a value, a list or a range");
  return {{spec, path}};
}

std::vector<Point> expand_node(const json& node, const std::string& path);

/// The most points a sweep may have (docs/sweeps.md). Checked before the points are made, so
/// that a product of 10^12 is refused at once instead of exhausting memory.
constexpr std::size_t kMaxSweepPoints = 1'000'000;

void check_points(std::size_t n, const std::string& path, const std::string& what) {
  if (n > kMaxSweepPoints)
    throw SweepError(path, what + " makes more than " + std::to_string(kMaxSweepPoints) +
                               " points (the limit of one sweep; split it into several)");
}

std::vector<Point> combine(const std::string& kind, const json& children, const std::string& path) {
  if (!children.is_array() || children.empty())
    throw SweepError(path, show(children).substr(0, 60) + ": " + kind + " takes a non-empty list of sweep nodes");
  std::vector<std::vector<Point>> parts;
  for (std::size_t k = 0; k < children.size(); ++k)
    parts.push_back(expand_node(children[k], path + "[" + std::to_string(k) + "]"));
  std::vector<Point> out;
  if (kind == "union") {
    std::size_t total = 0;
    for (const auto& p : parts) total += p.size();
    check_points(total, path, "this union");
    out.reserve(total);
    for (auto& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
  }
  if (kind == "zip") {
    for (std::size_t k = 1; k < parts.size(); ++k)
      if (parts[k].size() != parts[0].size())
        throw SweepError(path + "[" + std::to_string(k) + "]", std::to_string(parts[k].size()) +
                                                                   " points: zip needs equal lengths, the first has " +
                                                                   std::to_string(parts[0].size()));
    for (std::size_t i = 0; i < parts[0].size(); ++i) {
      Point p;
      for (std::size_t k = 0; k < parts.size(); ++k)
        for (auto& [name, t] : parts[k][i]) {
          if (p.count(name)) throw SweepError(t.path, "parameter " + name + " is set twice in one zip");
          p[name] = t;
        }
      out.push_back(std::move(p));
    }
    return out;
  }
  // product: the first child varies slowest
  out = {Point{}};
  std::size_t total = 1;
  for (const auto& part : parts) {  // sizes are <= the limit each: the products below cannot overflow
    total *= part.size();
    check_points(total, path, "this product");
  }
  for (const auto& part : parts) {
    std::vector<Point> next;
    next.reserve(out.size() * part.size());
    for (const Point& a : out)
      for (const Point& b : part) {
        Point p = a;
        for (auto& [name, t] : b) {
          if (p.count(name)) throw SweepError(t.path, "parameter " + name + " is set twice in one product");
          p[name] = t;
        }
        next.push_back(std::move(p));
      }
    out.swap(next);
  }
  return out;
}

std::vector<Point> expand_node(const json& node, const std::string& path) {
  if (!node.is_object() || node.empty())
    throw SweepError(path, show(node).substr(0, 60) + ": a sweep node is a non-empty object");
  if (node.size() == 1) {
    const std::string k = node.begin().key();
    if (k == "product" || k == "zip" || k == "union") return combine(k, node.begin().value(), path + "." + k);
  }
  // an axes object: each key a parameter, several keys are their product
  json axes = json::array();
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string p = path + "." + it.key();
    if (it.key() == "product" || it.key() == "zip" || it.key() == "union")
      throw SweepError(p, "a combinator must be the only key of its node");
    if (!sweepable().count(it.key())) throw SweepError(p, "unknown parameter (known: " + known_list() + ")");
  }
  std::vector<Point> out = {Point{}};
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::vector<Tagged> vals = values_of(it.value(), path + "." + it.key());
    check_points(out.size() * vals.size(), path, "these axes");  // both <= the limit: no overflow
    std::vector<Point> next;
    next.reserve(out.size() * vals.size());
    for (const Point& a : out)
      for (const Tagged& v : vals) {
        Point p = a;
        p[it.key()] = v;
        next.push_back(std::move(p));
      }
    out.swap(next);
  }
  return out;
}

double as_number(const Tagged& t, const std::string& name) {
  if (t.value.is_number()) return t.value.get<double>();
  if (t.value.is_boolean()) return t.value.get<bool>() ? 1 : 0;
  if (t.value.is_string() && t.value.get<std::string>() == "inf") return INFINITY;
  throw SweepError(t.path, show(t.value) + ": " + name + " must be a number here");
}

/// The names an expression uses (identifiers, whole words: E_w does not use w).
std::set<std::string> identifiers(const std::string& expr) {
  std::set<std::string> out;
  for (std::size_t i = 0; i < expr.size();) {
    const unsigned char ch = static_cast<unsigned char>(expr[i]);
    if (std::isalpha(ch) || ch == '_') {
      std::size_t k = i;
      while (k < expr.size() && (std::isalnum(static_cast<unsigned char>(expr[k])) || expr[k] == '_')) ++k;
      out.insert(expr.substr(i, k - i));
      i = k;
    } else if (std::isdigit(ch) || ch == '.') {  // a number, with its exponent (1e3 is not "e3")
      while (i < expr.size() && (std::isalnum(static_cast<unsigned char>(expr[i])) || expr[i] == '.')) ++i;
    } else {
      ++i;
    }
  }
  return out;
}

/// Evaluates an expression with the point's numeric parameters as variables.
/// True if expr assigns (muparser's =, +=, -=, *=, /=): in a filter or a derived value that is a
/// typo for a comparison ("w = 3" would set w and count as true for every point).
bool assigns(const std::string& expr) {
  for (std::size_t i = 0; i < expr.size(); ++i) {
    if (expr[i] != '=') continue;
    const char before = i > 0 ? expr[i - 1] : ' ', after = i + 1 < expr.size() ? expr[i + 1] : ' ';
    if (after == '=') {
      ++i;  // "==": a comparison
      continue;
    }
    if (before != '<' && before != '>' && before != '!') return true;
  }
  return false;
}

double evaluate(const std::string& expr, const Point& point, const std::string& path) {
  if (assigns(expr))
    throw SweepError(path, "\"" + expr + "\": '=' assigns; compare with '==' (or <=, >=, !=)");
  mu::Parser parser;
  std::map<std::string, double> vars;
  for (const auto& [name, t] : point) {
    if (name.rfind("run.", 0) == 0) continue;
    // a dotted parameter is a variable with an underscore: dp.E_c -> dp_E_c
    std::string var = name;
    std::replace(var.begin(), var.end(), '.', '_');
    if (t.value.is_number() || t.value.is_boolean() || (t.value.is_string() && t.value.get<std::string>() == "inf"))
      vars[var] = as_number(t, name);
  }
  try {
    for (auto& [name, v] : vars) parser.DefineVar(name, &v);
    parser.DefineConst("inf", INFINITY);
    parser.SetExpr(expr);
    return parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw SweepError(path, "\"" + expr + "\": " + e.GetMsg());
  }
}

/// job.name = value, or job.group.field = value for a dotted name; path names the value's place
/// in the sweep file for a group that is not one ({"": 1e5, ".x": 0}: found by the fuzzer).
void set_field(json& job, const std::string& name, const json& value, const std::string& path) {
  const auto dot = name.find('.');
  if (dot == std::string::npos) {
    job[name] = value;
    return;
  }
  json& group = job[name.substr(0, dot)];
  if (!group.is_null() && !group.is_object())
    throw SweepError(path, "\"" + name.substr(0, dot) + "\" holds a value, not a group of parameters, so \"" + name +
                               "\" cannot be set");
  group[name.substr(dot + 1)] = value;
}

}  // namespace

std::string job_key(const SimConfig& c) {
  // without the settings that cannot change a finished run's result (checkpoint cadence,
  // trajectory output, the Verlet skin, the blow-up threshold: engine/parameters.cpp)
  return sha256_hex(c.key_json().dump() + "\nengine " BEVERLOO_VERSION);
}

Sweep Sweep::load(const std::string& path, std::string* text) {
  json j;
  try {
    j = read_json_file(path, text);  // limits: engine/json_file.h
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    throw SweepError(path, what.substr(e.field().size() + 2));
  }
  try {
    Sweep s = parse(j, std::filesystem::path(path).stem().string());
    s.file = path;
    return s;
  } catch (const SweepError& e) {
    throw SweepError(path, e.what());
  } catch (const ConfigError& e) {
    throw SweepError(path, e.what());
  }
}

Sweep Sweep::parse(const json& j, const std::string& default_name) {
  if (!j.is_object()) throw SweepError("(top level)", "a sweep file is a JSON object");
  static const std::set<std::string> keys = {"name", "comment", "base", "run", "sweep", "derived", "where", "replicas",
                                             "adaptive", "$schema"};
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!keys.count(it.key()))
      throw SweepError(it.key(), "unknown field (known: name, comment, base, run, sweep, derived, where, replicas, adaptive)");
  Sweep s;
  s.source = j;
  s.name = default_name;
  if (j.contains("name")) {
    if (!j["name"].is_string() || j["name"].get<std::string>().empty())
      throw SweepError("name", show(j["name"]) + ": must be a non-empty string");
    s.name = j["name"].get<std::string>();
  }
  if (j.contains("comment")) {
    if (!j["comment"].is_string()) throw SweepError("comment", show(j["comment"]) + ": must be a string");
    s.comment = j["comment"].get<std::string>();
  }
  for (const char* obj : {"base", "run", "derived"})
    if (j.contains(obj) && !j[obj].is_object()) throw SweepError(obj, show(j[obj]).substr(0, 60) + ": must be an object");
  if (j.contains("derived"))
    for (auto it = j["derived"].begin(); it != j["derived"].end(); ++it) {
      if (!it.value().is_string()) throw SweepError("derived." + it.key(), show(it.value()) + ": must be an expression string");
      if (!sweepable().count(it.key()) || it.key().find('.') != std::string::npos)
        throw SweepError("derived." + it.key(), "unknown parameter (known: " + known_list() + ")");
    }
  if (j.contains("where")) {
    if (!j["where"].is_array()) throw SweepError("where", show(j["where"]) + ": must be a list of expressions");
    for (std::size_t k = 0; k < j["where"].size(); ++k)
      if (!j["where"][k].is_string())
        throw SweepError("where[" + std::to_string(k) + "]", show(j["where"][k]) + ": must be an expression string");
  }
  if (j.contains("replicas") && (!j["replicas"].is_number_integer() || j["replicas"].get<long>() < 1 ||
                                 j["replicas"].get<long>() > 100000))
    throw SweepError("replicas", show(j["replicas"]) + ": must be an integer in [1, 100000]");
  if (j.contains("sweep")) (void)expand_node(j["sweep"], "sweep");  // structure errors now
  if (j.contains("adaptive")) (void)AdaptiveSpec::parse(j["adaptive"]);
  return s;
}

std::vector<JobSpec> Sweep::expand() const {
  if (file.empty()) return expand_points();
  try {
    return expand_points();
  } catch (const SweepError& e) {
    throw SweepError(file, e.what());
  } catch (const ConfigError& e) {
    throw SweepError(file, e.what());
  }
}

std::vector<JobSpec> Sweep::expand_points() const {
  const json& j = source;
  std::vector<Point> points = j.contains("sweep") ? expand_node(j["sweep"], "sweep") : std::vector<Point>{Point{}};
  const long replicas = j.value("replicas", 1L);
  if (replicas > 1) {
    std::vector<Point> with;
    for (const Point& p : points)
      for (long r = 0; r < replicas; ++r) {
        Point q = p;
        if (q.count("replica")) throw SweepError(q["replica"].path, "replica is set by \"replicas\"; do not sweep it too");
        q["replica"] = {r, "replicas"};
        with.push_back(std::move(q));
      }
    points.swap(with);
  }
  const json base = j.value("base", json::object());
  std::vector<JobSpec> jobs;
  jobs.reserve(points.size());
  std::set<std::string> seen;
  for (Point& p : points) {
    // base values that the sweep labels (lambda, dissipation_scale) also take part in expressions
    for (const char* label : {"lambda", "dissipation_scale"})
      if (!p.count(label) && base.contains(label)) p[label] = {base[label], std::string("base.") + label};
    for (auto it = base.begin(); it != base.end(); ++it)
      if (!p.count(it.key()) && (it.value().is_number() || it.value().is_boolean()))
        p[it.key()] = {it.value(), "base." + it.key()};
    // derived parameters: evaluated until all are resolved (they may use each other)
    std::set<std::string> pending;
    if (j.contains("derived"))
      for (auto it = j["derived"].begin(); it != j["derived"].end(); ++it) pending.insert(it.key());
    std::set<std::string> derived_names = pending;
    while (!pending.empty()) {
      bool progress = false;
      for (auto it = pending.begin(); it != pending.end();) {
        const std::string expr = j["derived"][*it].get<std::string>();
        const std::set<std::string> uses = identifiers(expr);
        if (uses.count(*it)) throw SweepError("derived." + *it, "\"" + expr + "\": refers to itself");
        bool ready = true;
        for (const auto& other : pending)
          if (other != *it && uses.count(other)) ready = false;
        if (!ready) {
          ++it;
          continue;
        }
        const double v = evaluate(expr, p, "derived." + *it);
        p[*it] = {std::isinf(v) ? json("inf") : json(v), "derived." + *it};
        it = pending.erase(it);
        progress = true;
      }
      if (!progress) throw SweepError("derived", "the derived parameters depend on each other in a cycle");
    }
    bool keep = true;
    if (j.contains("where"))
      for (std::size_t k = 0; k < j["where"].size() && keep; ++k)
      {
        const std::string path = "where[" + std::to_string(k) + "]";
        const double v = evaluate(j["where"][k].get<std::string>(), p, path);
        if (std::isnan(v)) throw SweepError(path, "\"" + j["where"][k].get<std::string>() + "\": is NaN for a point (not a yes or no)");
        keep = v != 0;
      }
    if (!keep) continue;

    JobSpec spec;
    json job = base;
    job.erase("lambda");
    job.erase("dissipation_scale");
    if (j.contains("run")) {
      json& run = job["run"];
      if (!run.is_null() && !run.is_object())
        throw SweepError("base.run", show(run) + ": must be an object of run controls (as the top-level \"run\")");
      run.update(j["run"]);
    }
    const bool sets_zeta = (p.count("zeta") && p["zeta"].path.rfind("base.", 0) != 0) || derived_names.count("zeta");
    const bool sets_mu = (p.count("mu") && p["mu"].path.rfind("base.", 0) != 0) || derived_names.count("mu");
    for (auto& [name, t] : p) {
      if (name == "lambda" || name == "dissipation_scale") continue;
      set_field(job, name, t.value, t.path);
    }
    if (p.count("dissipation_scale")) spec.dissipation_scale = as_number(p["dissipation_scale"], "dissipation_scale");
    if (p.count("lambda")) {
      const double lambda = as_number(p["lambda"], "lambda");
      if (lambda < 0 || std::isnan(lambda)) throw SweepError(p["lambda"].path, show(p["lambda"].value) + ": lambda must be >= 0 or \"inf\"");
      spec.lambda = lambda;
      if (!sets_zeta && !sets_mu) {
        const double s = spec.dissipation_scale.value_or(1.0);
        if (s <= 0) throw SweepError(p["dissipation_scale"].path, "dissipation_scale must be > 0");
        const derived::ZetaMu d = derived::on_lambda_axis(lambda, s);
        job["zeta"] = d.zeta;
        job["mu"] = d.mu;
      }
    }
    try {
      spec.config = SimConfig::from_json(job);
      (void)choose_time_step(spec.config);  // an explicit dt the stiffest term cannot take
      // lambda means (zeta + drag_rate M(sigma_avg)) / mu_t (job-file.md) in every job: an axis
      // whose zeta and mu a fixed mu_t or drag_rate overrides would label jobs with a lambda
      // they do not have (all of one lambda with mu_t fixed): refused, not stored
      if (spec.lambda) {
        const std::optional<double> actual = derived::lambda(spec.config);
        const double want = *spec.lambda;
        const bool same = actual && (std::isinf(want) ? std::isinf(*actual)
                                                      : std::fabs(*actual - want) <= 1e-12 * std::max(1.0, want));
        if (!same)
          throw SweepError(p["lambda"].path,
                           show(p["lambda"].value) + ": the job's own lambda = (zeta + drag_rate M) / mu_t is " +
                               (actual ? (std::isinf(*actual) ? std::string("inf") : show(json(*actual))) : std::string("undefined")) +
                               " (mu_t, mu_n or drag_rate fixed beside the lambda axis override the zeta and mu it sets);"
                               " set zeta, mu_t and drag_rate directly (e.g. through \"derived\") instead");
      }
    } catch (const ConfigError& e) {
      const std::string field = e.field();
      std::string path = "base." + field, value;
      if (field.rfind("run.", 0) == 0 && j.contains("run") && j["run"].contains(field.substr(4))) {
        path = field;
        value = show(j["run"][field.substr(4)]) + ": ";
      }
      for (const auto& [name, t] : p)
        if (name == field || (field.rfind("theta_w", 0) == 0 && name == "theta_w_deg")) {
          path = t.path;
          value = show(t.value) + ": ";
        }
      if (value.empty() && field.find('.') == std::string::npos && job.contains(field)) value = show(job[field]) + ": ";
      const std::string what = e.what();
      throw SweepError(path, value + what.substr(what.find(": ") + 2));
    }
    spec.job = spec.config.to_json();
    spec.key = job_key(spec.config);
    json point = json::object();
    for (auto& [name, t] : p)
      if (t.path.rfind("base.", 0) != 0) point[name] = t.value;
    spec.point = point;
    if (!seen.insert(spec.key).second) continue;  // the same job twice in one sweep runs once
    jobs.push_back(std::move(spec));
  }
  if (jobs.empty())
    throw SweepError(j.contains("where") ? "where" : "sweep", "the sweep makes no jobs (every point is filtered out)");
  return jobs;
}

}  // namespace beverloo
