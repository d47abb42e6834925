#include "campaign_runs.h"

#include <cmath>
#include <sstream>

#include "core/digest.h"
#include "engine/config.h"
#include "engine/parameters.h"
#include "series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;
std::string fmt(double v, int digits = 4) { return table_number(v, digits); }

/// A job without what varies within one series: the width, the replica, the seed, and
/// run.min_time (a job given more flow time continues its point; no job made before that row
/// existed carries it, so every earlier series key stays what it was).
json series_job_of(const json& job) {
  json series_job = job;
  for (const char* k : {"w", "replica", "seed"}) series_job.erase(k);
  if (series_job.contains("run")) {
    series_job["run"].erase("min_time");
    if (series_job["run"].empty()) series_job.erase("run");
  }
  return series_job;
}

/// Of the runs of one trajectory (the same w, replica and seed in one series: they differ only
/// in run.min_time), the one that ran longest holds the others' flow: only it is a point.
void drop_continued_runs(Series& s, std::vector<RunRecord>& runs) {
  std::vector<RunRecord> kept_runs;
  std::vector<std::string> kept_keys;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    bool longer_exists = false;
    for (std::size_t j = 0; j < runs.size() && !longer_exists; ++j)
      longer_exists = j != i && runs[j].w == runs[i].w && runs[j].replica == runs[i].replica && runs[j].seed == runs[i].seed &&
                      (runs[j].end_time > runs[i].end_time || (runs[j].end_time == runs[i].end_time && j < i));
    if (longer_exists) {
      ++s.continued;
      continue;
    }
    kept_runs.push_back(runs[i]);
    kept_keys.push_back(s.job_keys[i]);
  }
  runs = std::move(kept_runs);
  s.job_keys = std::move(kept_keys);
}
}  // namespace

std::string series_key_of(const nlohmann::json& job) { return sha256_hex(series_job_of(job).dump()); }

CampaignRuns read_campaign_runs(db::Database& db, const CampaignScope& scope, FlowRate rate) {
  CampaignRuns out;
  // a clogged run's Q' is as missing as its Q (0): coalesce keeps the row
  const std::string columns = rate == FlowRate::QPrime ? "coalesce(r.Q_prime, 0), coalesce(r.Q_prime_err, 0)" : "r.Q, r.Q_err";
  db::Statement st = db.prepare(
      "SELECT j.key, j.job_json, " + columns + ", r.clogged, r.status, coalesce(r.clog_time, -1), r.steps, r.dt, r.window_start, r.window_end, r.force_ratio, "
      // summary_json: force_ratio_err is a generated column only once a binary that knows it
      // has opened the store (the report may read a campaign older than the field)
      "json_extract(r.summary_json, '$.force_ratio_err') FROM jobs j "
      "JOIN (" + scope.jobs_in_scope_sql() + ") c ON c.job_key = j.key JOIN results r ON r.job_key = j.key ORDER BY c.ord");
  std::map<std::string, std::size_t> index;
  std::vector<json> series_jobs;  // per series, for labels that tell them apart
  while (st.step()) {
    json job = json::parse(st.get_text(1));
    const double w = job["w"].get<double>();
    const json series_job = series_job_of(job);
    const std::string key = series_key_of(job);
    if (!index.count(key)) {
      Series s;
      s.key = key;
      s.model = job.value("model", std::string("sp"));
      s.dimension = job["dimension"];
      s.N = job["N"];
      std::ostringstream stiffness;
      if (s.is_dp()) {
        const json& dp = job.at("dp");
        s.n_v = dp.at("n_v");
        s.K_a = dp.at("K_a");
        s.K_l = dp.at("K_l");
        s.K_b = dp.at("K_b");
        s.E_c = dp.at("E_c");
        stiffness << "DP " << (s.model == "dp_rough" ? "rough" : "smooth") << " K_l=" << fmt(s.K_l) << " K_b=" << fmt(s.K_b)
                  << " E_c=" << fmt(s.E_c);
      } else {
        s.E_sp = job.at("E_sp");
        stiffness << "SP E_sp=" << fmt(s.E_sp);
      }
      s.stiffness = stiffness.str();
      s.zeta = job["zeta"];
      s.mu = job["mu"];
      s.drag_rate = job.value("drag_rate", 0.0);
      if (job.contains("mu_n")) s.mu_n = job["mu_n"].get<double>();
      if (job.contains("mu_t")) s.mu_t = job["mu_t"].get<double>();
      s.lambda = derived::lambda(SimConfig::from_json(job)).value_or(NAN);
      s.theta_left = job["theta_w_left_deg"];
      s.theta_right = job["theta_w_right_deg"];
      json base = series_job;
      base.erase("zeta");
      base.erase("mu");
      base.erase("drag_rate");
      base.erase("mu_n");  // a friction split belongs to the friction: limits match on mu and mu_n
      base.erase("mu_t");
      s.base_key = sha256_hex(base.dump());
      base.erase("theta_w_left_deg");
      base.erase("theta_w_right_deg");
      s.angle_free_key = sha256_hex(base.dump());
      json sized = series_job;
      sized.erase("N");
      s.size_free_key = sha256_hex(sized.dump());
      json unstiffened = series_job;
      unstiffened.erase("E_sp");
      s.stiffness_free_key = sha256_hex(unstiffened.dump());
      json system = series_job;  // what the model's own settings leave: the flow's conditions
      for (const char* k : {"model", "E_sp", "sp_contact_law", "dp", "E_w", "run", "dt", "fire", "max_overlap", "skin", "observables"})
        system.erase(k);
      s.model_free_key = sha256_hex(system.dump());
      out.base_job_of[key] = base;
      series_jobs.push_back(series_job);
      std::ostringstream label;
      label << s.dimension << "D " << s.stiffness << " lambda=" << format_lambda(s.lambda) << " (zeta="
            << fmt(s.zeta, 3);
      if (s.drag_rate > 0) label << ", drag_rate=" << fmt(s.drag_rate, 3);
      label << ", mu=" << fmt(s.mu, 3);
      if (s.mu_n) label << ", mu_n=" << fmt(*s.mu_n, 3);
      if (s.mu_t) label << ", mu_t=" << fmt(*s.mu_t, 3);
      label << ")";
      if (s.theta_left != 90 || s.theta_right != 90) label << " theta=" << fmt(s.theta_left) << "/" << fmt(s.theta_right);
      label << " N=" << s.N;
      s.drain = !job.value("reinject", true);
      if (s.drain) label << " draining (Q = c0 t0)";
      s.label = label.str();
      index[key] = out.series.size();
      out.series.push_back(s);
    }
    out.series[index[key]].job_keys.push_back(st.get_text(0));
    RunRecord r;
    r.w = w;
    r.replica = job.value("replica", 0);
    if (job.contains("seed")) r.seed = job["seed"].dump();
    r.Q = st.get_double(2);
    r.Q_err = st.get_double(3);
    r.clogged = st.get_int(4) != 0;
    r.time_limited = st.get_text(5) == "time_limit" || st.get_text(5) == "unreachable";  // Q with its larger error
    r.clog_time = st.get_double(6);
    r.end_time = static_cast<double>(st.get_int(7)) * st.get_double(8);
    r.window_start = st.get_double(9);
    r.window_end = st.get_double(10);
    r.t_max = job.contains("run") ? job["run"].value("t_max", 0.0) : 0.0;
    if (!st.is_null(11)) r.force_ratio = st.get_double(11);
    if (!st.is_null(12)) r.force_ratio_err = st.get_double(12);
    out.runs[key].push_back(r);
  }
  for (Series& s : out.series) drop_continued_runs(s, out.runs[s.key]);
  {
    std::vector<std::string> labels;
    for (const Series& s : out.series) labels.push_back(s.label);
    disambiguate_labels(labels, series_jobs);
    for (std::size_t i = 0; i < labels.size(); ++i) out.series[i].label = labels[i];
  }
  return out;
}

}  // namespace beverloo
