#include "series_labels.h"

#include <algorithm>
#include <map>
#include <set>

#include "engine/parameters.h"
#include "reports/number_format.h"

namespace beverloo {
namespace {
using nlohmann::json;

/// "/reinjection/rule" -> "reinjection.rule"
std::string dotted(const std::string& pointer) {
  std::string p = pointer.substr(1);
  std::replace(p.begin(), p.end(), '/', '.');
  return p;
}

std::string value_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return format_value(v.get<double>(), 4);
  return v.dump();
}

/// The table's default of a path that a canonical job leaves out (omitted at its default).
std::string default_text(const std::string& path) {
  for (const ParamSpec& p : job_parameters())
    if (p.path == path) {
      std::string d(p.default_text);
      if (d.size() >= 2 && d.front() == '"' && d.back() == '"') d = d.substr(1, d.size() - 2);
      return d;
    }
  return "(absent)";
}

/// Position of a path in the parameter table (unknown paths after all known ones).
std::size_t table_rank(const std::string& path) {
  const auto& table = job_parameters();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].path == path) return i;
  return table.size();
}

}  // namespace

void disambiguate_labels(std::vector<std::string>& labels, const std::vector<json>& jobs) {
  std::map<std::string, std::vector<std::size_t>> by_label;
  for (std::size_t i = 0; i < labels.size(); ++i) by_label[labels[i]].push_back(i);
  for (const auto& [label, members] : by_label) {
    if (members.size() < 2) continue;
    std::vector<json> flat;
    std::set<std::string> paths;
    for (std::size_t i : members) {
      json f = jobs[i].flatten();
      for (auto it = f.begin(); it != f.end();) it = it->is_null() ? f.erase(it) : std::next(it);  // empty groups
      for (const auto& [p, v] : f.items()) paths.insert(p);
      flat.push_back(std::move(f));
    }
    std::vector<std::string> differing;
    for (const std::string& p : paths) {
      const json* first = flat[0].contains(p) ? &flat[0][p] : nullptr;
      for (const json& f : flat) {
        const json* here = f.contains(p) ? &f[p] : nullptr;
        if ((first == nullptr) != (here == nullptr) || (first && *first != *here)) {
          differing.push_back(p);
          break;
        }
      }
    }
    std::stable_sort(differing.begin(), differing.end(), [](const std::string& a, const std::string& b) {
      const std::size_t ra = table_rank(dotted(a)), rb = table_rank(dotted(b));
      return ra != rb ? ra < rb : a < b;
    });
    for (std::size_t m = 0; m < members.size(); ++m)
      for (const std::string& p : differing)
        labels[members[m]].append(" ").append(dotted(p)).append("=").append(flat[m].contains(p) ? value_text(flat[m][p])
                                                                                                : default_text(dotted(p)));
  }
}

}  // namespace beverloo
