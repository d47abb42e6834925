#include "sweep_schema.h"

#include <string>

#include "engine/parameters.h"

namespace beverloo {
namespace {
using nlohmann::json;

json number_schema(const ParamSpec& p, const char* type) {
  json s = {{"type", type}};
  if (p.has_lo()) s[p.lo_open ? "exclusiveMinimum" : "minimum"] = p.lo;
  if (p.has_hi()) s[p.hi_open ? "exclusiveMaximum" : "maximum"] = p.hi;
  return s;
}

json row_schema(const ParamSpec& p) {
  switch (p.type) {
    case ParamType::Real:
    case ParamType::OptionalReal:
      return number_schema(p, "number");
    case ParamType::Integer:
    case ParamType::Integer64:
      return number_schema(p, "integer");
    case ParamType::Seed:
      return {{"type", "integer"}, {"minimum", 0}};
    case ParamType::Boolean:
      return {{"type", "boolean"}};
    case ParamType::RealOrAuto:
      return {{"oneOf", json::array({number_schema(p, "number"), {{"const", "auto"}}})}};
    case ParamType::Text: {
      if (p.allowed.empty()) return {{"type", "string"}};
      json e = json::array();
      std::string all(p.allowed);
      for (std::size_t a = 0, b; a <= all.size(); a = b + 1) {
        b = all.find(',', a);
        if (b == std::string::npos) b = all.size();
        e.push_back(all.substr(a, b - a));
      }
      return {{"enum", e}};
    }
  }
  return json::object();
}

json object_of(const json& properties) {
  return {{"type", "object"}, {"additionalProperties", false}, {"properties", properties}};
}

}  // namespace

json parameter_schema_defs() {
  json top = json::object(), groups = json::object();
  json top_names = json::array(), group_names = json::object();
  for (const ParamSpec& p : job_parameters()) {
    const std::string path(p.path);
    const auto dot = path.find('.');
    if (dot == std::string::npos) {
      top[path] = row_schema(p);
      if (p.sweepable) top_names.push_back(path);
    } else {
      const std::string g = path.substr(0, dot);
      groups[g][path.substr(dot + 1)] = row_schema(p);
      if (p.sweepable) group_names[g].push_back(path);
    }
  }
  // the sweep's own labels (docs/sweeps.md): they set zeta and mu
  top["lambda"] = {{"oneOf", json::array({{{"type", "number"}, {"minimum", 0}}, {{"const", "inf"}}})}};
  top["dissipation_scale"] = {{"type", "number"}, {"exclusiveMinimum", 0}};
  top_names.push_back("lambda");
  top_names.push_back("dissipation_scale");
  top["comment"] = {{"type", "string"}};
  for (auto it = groups.begin(); it != groups.end(); ++it)
    top[it.key()] = it.key() == "run" ? json{{"$ref", "#/$defs/run"}} : object_of(it.value());
  json any = json::array({{{"$ref", "#/$defs/topParameter"}}});
  for (auto it = group_names.begin(); it != group_names.end(); ++it) any.push_back({{"enum", it.value()}});
  return {{"job", object_of(top)},
          {"run", object_of(groups["run"])},
          {"topParameter", {{"enum", top_names}}},
          {"parameter", {{"anyOf", any}}}};
}

}  // namespace beverloo
