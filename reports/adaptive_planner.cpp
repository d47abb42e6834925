#include "adaptive_planner.h"

#include <map>
#include <set>
#include <sstream>

#include "campaign_fits.h"
#include "campaign_runs.h"
#include "next_width.h"
#include "number_format.h"
#include "orchestrator/sweep/adaptive_spec.h"

namespace beverloo {
namespace {
using nlohmann::json;

struct SeriesJobs {
  json template_job;        ///< its first job (point order): what an added job copies
  bool busy = false;        ///< a job pending or running
  std::set<std::string> keys;
};

struct SeriesDecisions {
  bool stopped = false;
  int added = 0;
};

std::string num(double v) { return table_number(v, 3); }

PlanDecision stop(const std::string& series, const std::string& reason, const Series* s = nullptr) {
  PlanDecision d;
  d.series_key = series;
  d.action = "stop";
  d.reason = reason;
  if (s && s->fit) {
    d.k_err = s->fit->k_err;
    d.beta_err = s->fit->beta_err;
  }
  if (s)
    for (const SeriesPoint& p : s->points) d.flowing_points += p.flowing();
  return d;
}

/// The job of `series` at width w: the smallest replica whose key the campaign does not hold.
JobSpec job_at(const SeriesJobs& series, double w) {
  for (int replica = 0;; ++replica) {
    json job = series.template_job;
    job["w"] = w;
    job["replica"] = replica;
    JobSpec spec;
    spec.config = SimConfig::from_json(job);
    spec.key = job_key(spec.config);
    if (series.keys.count(spec.key)) continue;
    spec.job = spec.config.to_json();
    spec.point = {{"w", w}, {"replica", replica}, {"adaptive", true}};
    return spec;
  }
}
}  // namespace

std::vector<PlanDecision> AdaptivePlanner::plan(db::Database& db, std::int64_t campaign) {
  std::optional<AdaptiveSpec> spec;
  {
    db::Statement st = db.prepare("SELECT sweep_json FROM campaigns WHERE id = ?1");
    st.bind(1, campaign);
    if (!st.step()) return {};
    spec = AdaptiveSpec::of_sweep(json::parse(st.get_text(0)));
  }
  if (!spec) return {};

  std::map<std::string, SeriesJobs> jobs;
  std::vector<std::string> order;  // series in the campaign's point order
  {
    db::Statement st = db.prepare(
        "SELECT j.key, j.job_json, j.state FROM jobs j JOIN campaign_jobs c ON c.job_key = j.key "
        "WHERE c.campaign_id = ?1 ORDER BY c.point_index");
    st.bind(1, campaign);
    while (st.step()) {
      const json job = json::parse(st.get_text(1));
      const std::string series = series_key_of(job);
      auto [it, is_new] = jobs.try_emplace(series);
      if (is_new) {
        it->second.template_job = job;
        order.push_back(series);
      }
      it->second.keys.insert(st.get_text(0));
      const std::string state = st.get_text(2);
      it->second.busy = it->second.busy || state == "pending" || state == "running";
    }
  }
  std::map<std::string, SeriesDecisions> past;
  {
    db::Statement st = db.prepare("SELECT series_key, action FROM adaptive_decisions WHERE campaign_id = ?1");
    st.bind(1, campaign);
    while (st.step()) {
      SeriesDecisions& d = past[st.get_text(0)];
      if (st.get_text(1) == "stop") d.stopped = true;
      else ++d.added;
    }
  }

  bool any_due = false;
  for (const std::string& key : order) any_due = any_due || (!jobs[key].busy && !past[key].stopped);
  if (!any_due) return {};
  const std::vector<Series> fitted = fit_campaign_series(db, campaign);
  std::map<std::string, const Series*> by_key;
  for (const Series& s : fitted) by_key[s.key] = &s;

  DesignTargets targets;
  targets.k_err = spec->k_err;
  targets.beta_err = spec->beta_err;
  std::vector<PlanDecision> out;
  for (const std::string& key : order) {
    const SeriesJobs& sj = jobs[key];
    const SeriesDecisions& sd = past[key];
    if (sj.busy || sd.stopped) continue;
    const auto found = by_key.find(key);
    if (found == by_key.end()) {
      out.push_back(stop(key, "no job of the series finished with a flow rate"));
      continue;
    }
    const Series& s = *found->second;
    if (!s.fit) {
      out.push_back(stop(key, "cannot be fitted: " + s.message, &s));
      continue;
    }
    std::vector<double> w, Q, err;
    s.flowing_columns(w, Q, err);
    DesignAdvice advice;
    try {
      advice = next_width(*s.fit, w, Q, err, spec->w_lo, spec->w_hi, spec->w_step, targets);
    } catch (const FitError& e) {
      out.push_back(stop(key, std::string("no design: ") + e.what(), &s));
      continue;
    }
    if (advice.targets_met) {
      out.push_back(stop(key, "targets met: k_err " + num(advice.k_err_now) + ", beta_err " + num(advice.beta_err_now), &s));
      continue;
    }
    if (sd.added >= spec->max_added_jobs) {
      out.push_back(stop(key, "budget spent: " + std::to_string(sd.added) + " jobs added (max_added_jobs), k_err " +
                                  num(advice.k_err_now) + ", beta_err " + num(advice.beta_err_now), &s));
      continue;
    }
    PlanDecision d;
    d.series_key = key;
    d.action = "add";
    d.job = job_at(sj, advice.next->w);
    d.k_err = advice.k_err_now;
    d.beta_err = advice.beta_err_now;
    d.k_err_after = advice.next->k_err_after;
    d.beta_err_after = advice.next->beta_err_after;
    d.flowing_points = static_cast<int>(w.size());
    std::ostringstream why;
    why << "w = " << num(advice.next->w) << " (replica " << d.job->config.replica << "): k_err " << num(advice.k_err_now)
        << " -> " << num(advice.next->k_err_after) << ", beta_err " << num(advice.beta_err_now) << " -> "
        << num(advice.next->beta_err_after) << " predicted, cost " << num(advice.next->relative_cost)
        << " x a run at the median Q";
    d.reason = why.str();
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace beverloo
