#include "job_explain.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>

namespace beverloo {
namespace {

void flatten_into(const nlohmann::json& j, const std::string& prefix, std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object() && !j.empty()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      flatten_into(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), out);
  } else {
    out.emplace_back(prefix, j.dump());
  }
}

StoredJob read_stored(db::Database& db, const std::string& key) {
  StoredJob s;
  s.key = key;
  db::Statement st = db.prepare(
      "SELECT j.state, j.engine_version, coalesce(r.status, ''), coalesce(r.Q, 0), coalesce(r.Q_err, 0) "
      "FROM jobs j LEFT JOIN results r ON r.job_key = j.key WHERE j.key = ?1");
  st.bind(1, key);
  if (st.step()) {
    s.state = st.get_text(0);
    s.engine_version = st.get_text(1);
    s.result_status = st.get_text(2);
    s.Q = st.get_double(3);
    s.Q_err = st.get_double(4);
  }
  return s;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> flatten_json(const nlohmann::json& j) {
  std::vector<std::pair<std::string, std::string>> out;
  flatten_into(j, "", out);
  return out;
}

std::vector<std::string> identity_free_paths(const SimConfig& c) {
  std::set<std::string> in_key;
  for (const auto& [path, value] : flatten_json(c.key_json())) in_key.insert(path);
  std::vector<std::string> out;
  for (const auto& [path, value] : flatten_json(c.to_json()))
    if (!in_key.count(path)) out.push_back(path);
  return out;
}

std::pair<std::string, nlohmann::json> find_stored_job(db::Database& db, const std::string& key_or_prefix) {
  const bool hex = !key_or_prefix.empty() &&
                   std::all_of(key_or_prefix.begin(), key_or_prefix.end(), [](char ch) { return std::isxdigit(static_cast<unsigned char>(ch)); });
  if (!hex || key_or_prefix.size() < 8 || key_or_prefix.size() > 64)
    throw std::invalid_argument("a job key is 8 to 64 hexadecimal digits (a prefix of the sha256 key), or give a job file");
  std::string lower = key_or_prefix;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
  // the key is hexadecimal: a prefix range needs no LIKE escaping
  db::Statement st = db.prepare("SELECT key, job_json FROM jobs WHERE key >= ?1 AND key < ?1 || 'g' ORDER BY key LIMIT 2");
  st.bind(1, lower);
  std::vector<std::pair<std::string, std::string>> hits;
  while (st.step()) hits.emplace_back(st.get_text(0), st.get_text(1));
  if (hits.empty()) throw std::invalid_argument("no stored job has a key starting with " + lower);
  if (hits.size() > 1) throw std::invalid_argument("more than one stored job has a key starting with " + lower + ": give more digits");
  return {hits[0].first, nlohmann::json::parse(hits[0].second)};
}

namespace {
/// How far apart the differing values are: per field |a - b| / max(|a|, |b|) for two numbers,
/// 1 otherwise (a text, an absent field); summed.
double relative_spread(const std::vector<FieldDifference>& diff) {
  double sum = 0;
  for (const FieldDifference& d : diff) {
    char* end_a = nullptr;
    char* end_b = nullptr;
    const double a = std::strtod(d.asked.c_str(), &end_a), b = std::strtod(d.stored.c_str(), &end_b);
    const bool numbers = !d.asked.empty() && !d.stored.empty() && *end_a == '\0' && *end_b == '\0' &&
                         std::isfinite(a) && std::isfinite(b);
    const double scale = std::max(std::fabs(a), std::fabs(b));
    sum += numbers ? (scale > 0 ? std::fabs(a - b) / scale : 0.0) : 1.0;
  }
  return sum;
}
}  // namespace

JobExplanation explain_job(db::Database& db, const std::string& key, const nlohmann::json& job,
                           const std::vector<std::string>& identity_free) {
  JobExplanation out;
  out.key = key;
  const std::set<std::string> free(identity_free.begin(), identity_free.end());
  std::map<std::string, std::string> asked;
  for (auto& [path, value] : flatten_json(job))
    if (!free.count(path)) asked[path] = value;
  {
    const StoredJob self = read_stored(db, key);
    if (!self.state.empty()) out.found = self;
  }
  if (out.found && (out.found->state == "done" || out.found->state == "clogged")) return out;
  // the nearest done (or clogged) job: fewest differing identity fields; among those the
  // smallest relative differences of the numbers (w = 5.5 is nearer 6 than 2.2); then by key
  db::Statement all = db.prepare("SELECT key, job_json, engine_version FROM jobs WHERE state IN ('done', 'clogged') ORDER BY key");
  std::size_t best = SIZE_MAX;
  double best_spread = 0;
  std::string best_key;
  std::vector<FieldDifference> best_diff;
  while (all.step()) {
    const std::string k = all.get_text(0);
    if (k == key) continue;
    ++out.stored_jobs;
    nlohmann::json stored;
    try {
      stored = nlohmann::json::parse(all.get_text(1));
    } catch (const nlohmann::json::exception&) {
      continue;  // not ours to judge here; `campaign status` and the coordinator report such rows
    }
    std::map<std::string, std::string> theirs;
    for (auto& [path, value] : flatten_json(stored))
      if (!free.count(path)) theirs[path] = value;
    std::vector<FieldDifference> diff;
    for (const auto& [path, value] : asked) {
      auto it = theirs.find(path);
      if (it == theirs.end())
        diff.push_back({path, value, "(absent)"});
      else if (it->second != value)
        diff.push_back({path, value, it->second});
      if (diff.size() > best) break;
    }
    for (const auto& [path, value] : theirs)
      if (!asked.count(path)) diff.push_back({path, "(absent)", value});
    if (diff.size() > best) continue;
    const double spread = relative_spread(diff);
    if (diff.size() < best || spread < best_spread) {
      best = diff.size();
      best_spread = spread;
      best_key = k;
      best_diff = std::move(diff);
    }
  }
  if (!best_key.empty()) {
    out.nearest = read_stored(db, best_key);
    out.differences = std::move(best_diff);
    out.only_engine_differs = out.differences.empty();
  }
  return out;
}

}  // namespace beverloo
