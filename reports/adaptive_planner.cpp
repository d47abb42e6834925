#include "adaptive_planner.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "campaign_fits.h"
#include "campaign_runs.h"
#include "crossover_groups.h"
#include "lambda_series.h"
#include "next_lambda.h"
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
  std::set<double> grid_widths;  ///< the widths of its jobs the sweep made (not the planner)
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

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The series' finished runs as next_width() prices them (adaptive.extend); run_index: the index
/// in `runs` of each of the costs' runs.
FlowTimeCosts flow_time_costs(const std::vector<RunRecord>& runs, std::vector<std::size_t>& run_index) {
  FlowTimeCosts c;
  std::vector<double> starts, exits_rel2;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunRecord& r = runs[i];
    const double window = r.window_end - r.window_start;
    if (r.clogged || !(r.Q > 0 && r.Q_err > 0 && window > 0)) continue;
    c.runs.push_back({r.w, r.Q_err, window});
    run_index.push_back(i);
    starts.push_back(r.window_start);
    exits_rel2.push_back(window * r.Q * (r.Q_err / r.Q) * (r.Q_err / r.Q));
  }
  c.start_t0 = median_of(starts);
  c.exits_rel2 = median_of(exits_rel2);
  return c;
}

/// The job that gives the finished run `key` its window again: the same job with run.min_time
/// at its end plus its window, on a check step (the run then stops there, its error rule met).
JobSpec extended_job(db::Database& db, const std::string& key, const RunRecord& run) {
  db::Statement st = db.prepare("SELECT job_json FROM jobs WHERE key = ?1");
  st.bind(1, key);
  if (!st.step()) throw std::runtime_error("the job " + key + " is not in the database");
  json job = json::parse(st.get_text(0));
  const double check = job.at("run").at("check_interval").get<double>();
  const double min_time = std::ceil((run.end_time + (run.window_end - run.window_start)) / check - 1e-9) * check;
  job["run"]["min_time"] = min_time;
  JobSpec spec;
  spec.config = SimConfig::from_json(job);
  spec.key = job_key(spec.config);
  spec.job = spec.config.to_json();
  spec.point = {{"w", run.w}, {"replica", run.replica}, {"min_time", min_time}, {"adaptive", true}};
  return spec;
}

/// The decisions of a beta(lambda) group are rows with this series_key: its added series' jobs
/// and its stop (the series keep their own rows, so a new series has its own budget of widths).
std::string group_key(const Crossover& g) { return "lambda_" + g.key.substr(0, 16); }

/// The free candidate lambda (free_candidate_log10_lambdas, as next_lambda's) strictly inside
/// the crossing's bracketing pair and nearest the crossing (ties to the smaller); none when the
/// bracket holds no such candidate.
std::optional<double> crossing_candidate(const MidpointCrossing& m, const std::vector<double>& group_lambdas,
                                         const LambdaAdaptiveSpec& spec) {
  const double lo = std::log10(m.lambda_lo), hi = std::log10(m.lambda_hi);
  std::optional<double> best;
  for (const double x : free_candidate_log10_lambdas(group_lambdas, spec.lambda_lo, spec.lambda_hi, spec.per_decade))
    if (x > lo && x < hi && (!best || std::fabs(x - m.log10_lambda) < std::fabs(*best - m.log10_lambda)))
      best = x;  // strict: ties to the smaller
  if (best) return std::pow(10.0, *best);
  return std::nullopt;
}

/// The lambda stage (adaptive_spec.h "lambda"): per beta(lambda) group not yet stopped, fit
/// the crossover and add one whole series (the grid's widths of its nearest series) at the lambda
/// next_lambda() chooses, or stop the group. Runs only when every series is decided.
void plan_lambda(db::Database& db, const LambdaAdaptiveSpec& spec, const CampaignFits& fits,
                 std::map<std::string, SeriesJobs>& jobs, std::map<std::string, SeriesDecisions>& past,
                 std::vector<PlanDecision>& out) {
  for (const Crossover& g : fits.crossovers) {
    const std::string gkey = group_key(g);
    if (past[gkey].stopped) continue;
    // series added to this group so far: the distinct series of its add rows' jobs
    std::set<std::string> added_series;
    {
      db::Statement st = db.prepare(
          "SELECT j.job_json FROM adaptive_decisions d JOIN jobs j ON j.key = d.job_key "
          "WHERE d.series_key = ?1 AND d.action = 'add'");
      st.bind(1, gkey);
      while (st.step()) added_series.insert(series_key_of(json::parse(st.get_text(0))));
    }
    auto stop_group = [&](const std::string& reason) {
      PlanDecision d;
      d.series_key = gkey;
      d.action = "stop";
      d.reason = g.label + ": " + reason;
      if (g.fit) {
        d.k_err = g.fit->log10_lambda_c_err;  // the group's rows: log10 lambda_c and b in k's and beta's columns
        d.beta_err = g.fit->b_err;
      }
      d.flowing_points = static_cast<int>(g.finite.size());
      out.push_back(std::move(d));
    };
    // one whole series at l_new (the grid's widths of its nearest series), each job's decision
    // described by `describe`; a lambda that cannot be placed stops the group instead
    auto add_series = [&](double l_new, const std::function<void(PlanDecision&, double w)>& describe) {
      // placed between the series that bracket it, the group's limits included (lambda_series.h)
      LambdaGroupJobs group_jobs;
      for (const Series* s : g.finite) group_jobs.finite.emplace_back(s->lambda, jobs[s->key].template_job);
      if (g.limit0) group_jobs.limit0 = &jobs[g.limit0->key].template_job;
      if (g.limit_inf) group_jobs.limit_inf = &jobs[g.limit_inf->key].template_job;
      // the finite series nearest below it (the lowest beyond the low end): whose grid widths it takes
      std::size_t below = 0;
      while (below + 1 < g.finite.size() && g.finite[below + 1]->lambda < l_new) ++below;
      const SeriesJobs& ta = jobs[g.finite[below]->key];
      LambdaJob made;
      try {  // a lambda the parameter table refuses (a drag rate beyond its range, say) stops the group
        made = job_at_lambda_in_group(group_jobs, l_new);
      } catch (const std::exception& e) {
        made.problem = e.what();
      }
      if (!made.job) {
        stop_group("cannot place lambda = " + num(l_new) + ": " + made.problem);
        return;
      }
      // the grid's widths: of that series if it has some (a series the planner added has none of
      // its own), else of any series of the group that has
      std::set<double> widths = ta.grid_widths;
      for (const Series* s : g.finite)
        if (widths.empty()) widths = jobs[s->key].grid_widths;
      if (widths.empty()) widths = {ta.template_job.at("w").get<double>()};
      for (const double w : widths) {
        json job = *made.job;
        job["w"] = w;
        job["replica"] = 0;
        PlanDecision d;
        d.series_key = gkey;
        d.action = "add";
        JobSpec spec_job;
        spec_job.config = SimConfig::from_json(job);
        spec_job.key = job_key(spec_job.config);
        spec_job.job = spec_job.config.to_json();
        spec_job.point = {{"w", w}, {"lambda", l_new}, {"replica", 0}, {"adaptive", true}};
        d.job = spec_job;
        d.flowing_points = static_cast<int>(g.finite.size());
        describe(d, w);
        out.push_back(std::move(d));
      }
    };
    const bool budget_spent = static_cast<int>(added_series.size()) >= spec.max_added_series;
    // where the exponents cross d - 1 first: a series at the crossing while the chord's
    // interpolation error exceeds its target (no sigmoid needed); `crossing_met` says why not
    std::string crossing_met;
    if (spec.crossing_interpolation_err) {
      const std::optional<MidpointCrossing> m = crossing_of_d_minus_1(g);
      std::vector<double> group_lambdas = g.unfitted_lambda;
      for (const Series* s : g.finite) group_lambdas.push_back(s->lambda);
      std::optional<double> l_new;
      const std::string interpolation =
          !m ? "" : std::isnan(m->interpolation) ? "unknown (no neighbouring lambda)" : num(m->interpolation);
      if (!m)
        crossing_met = "beta does not cross d - 1 among the measured lambdas";
      else if (!std::isnan(m->interpolation) && m->interpolation <= *spec.crossing_interpolation_err)
        crossing_met = "crossing interpolation err " + interpolation;
      else if (!(l_new = crossing_candidate(*m, group_lambdas, spec)))
        crossing_met = "the crossing as fine as per_decade " + std::to_string(spec.per_decade) +
                       " allows (no candidate lambda between " + num(m->lambda_lo) + " and " + num(m->lambda_hi) +
                       "), crossing interpolation err " + interpolation;
      if (crossing_met.empty()) {
        if (budget_spent)
          stop_group("budget spent: " + std::to_string(added_series.size()) +
                     " series added (max_added_series), crossing interpolation err " + interpolation);
        else
          add_series(*l_new, [&](PlanDecision& d, double w) {
            d.reason = g.label + ": new series at lambda = " + num(*l_new) + " (w = " + num(w) + "): beta crosses d - 1 at " +
                       num(std::pow(10.0, m->log10_lambda)) + " between " + num(m->lambda_lo) + " and " +
                       num(m->lambda_hi) + ", interpolation err " + interpolation;
          });
        continue;
      }
    }
    if (!spec.log10_lambda_c_err && !spec.b_err) {
      stop_group(crossing_met.rfind("the crossing as fine", 0) == 0 ? crossing_met : "targets met: " + crossing_met);
      continue;
    }
    // a singular fit, or one that takes series without a Beverloo law, is no measurement, but it
    // places the step: new lambdas go there
    const std::optional<CrossoverFit>& design_fit = g.fit ? g.fit : g.design_fit;
    if (!design_fit) {
      stop_group("the crossover cannot be fitted: " + g.message);
      continue;
    }
    std::vector<double> lambda, beta_err;
    for (const Series* s : g.finite) {
      lambda.push_back(s->lambda);
      // a series that follows no Beverloo law is not in the crossover fit: its lambda is taken,
      // but it tells the design nothing (error 0, as below); the design fit takes it, and so
      // does the design made from it
      beta_err.push_back(!g.fit || g.takes(s) ? s->fit->beta_err : 0);
    }
    // a series the group has but cannot fit still holds its lambda: no information (error 0),
    // but no new series there (it would be the same jobs again, and the group would add nothing)
    for (const double l : g.unfitted_lambda) {
      lambda.push_back(l);
      beta_err.push_back(0);
    }
    CrossoverAdvice advice;
    try {
      CrossoverTargets t;
      t.log10_lambda_c_err = spec.log10_lambda_c_err;
      t.b_err = spec.b_err;
      advice = next_lambda(g.dimension, *design_fit, lambda, beta_err, spec.lambda_lo, spec.lambda_hi, spec.per_decade, t);
    } catch (const FitError& e) {
      stop_group(std::string("no design: ") + e.what());
      continue;
    }
    const std::string errs =
        "log10 lambda_c err " + num(advice.log10_lambda_c_err_now) + ", b err " + num(advice.b_err_now);
    if (advice.targets_met) {
      stop_group("targets met: " + errs + (crossing_met.empty() ? "" : "; " + crossing_met));
      continue;
    }
    if (budget_spent) {
      stop_group("budget spent: " + std::to_string(added_series.size()) + " series added (max_added_series), " + errs);
      continue;
    }
    const double l_new = advice.next->lambda;
    add_series(l_new, [&](PlanDecision& d, double w) {
      d.k_err = advice.log10_lambda_c_err_now;
      d.beta_err = advice.b_err_now;
      d.k_err_after = advice.next->log10_lambda_c_err_after;
      d.beta_err_after = advice.next->b_err_after;
      const bool predicted = std::isfinite(advice.next->log10_lambda_c_err_after);
      d.reason = g.label + ": new series at lambda = " + num(l_new) + " (w = " + num(w) + "): " + errs +
                 (predicted ? " -> " + num(advice.next->log10_lambda_c_err_after) + ", " + num(advice.next->b_err_after) +
                                  " predicted"
                            : "; the step lies between series: a series on it (no prediction)");
    });
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
        "SELECT j.key, j.job_json, j.state, c.sweep_point FROM jobs j JOIN campaign_jobs c ON c.job_key = j.key "
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
      if (!json::parse(st.get_text(3)).value("adaptive", false)) it->second.grid_widths.insert(job.at("w").get<double>());
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

  bool any_due = false, any_busy = false;
  for (const std::string& key : order) {
    any_due = any_due || (!jobs[key].busy && !past[key].stopped);
    any_busy = any_busy || jobs[key].busy;
  }
  // the lambda stage may be due once every series is quiet and decided
  if (!any_due && !(spec->lambda && !any_busy)) return {};
  const CampaignFits fits = fit_campaign_with_crossovers(db, campaign);
  const std::vector<Series>& fitted = fits.series;
  std::map<std::string, const Series*> by_key;
  for (const Series& s : fitted) by_key[s.key] = &s;

  std::optional<CampaignRuns> campaign_runs;  // read once, for adaptive.extend
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
    std::optional<FlowTimeCosts> costs;
    std::vector<std::size_t> run_index;  // per costs->runs: its index in the series' runs
    const Series* read_series = nullptr;  // the series as read (its runs and job keys in parallel)
    if (spec->extend) {
      if (!campaign_runs) campaign_runs = read_campaign_runs(db, CampaignScope::one(campaign));
      for (const Series& c : campaign_runs->series)
        if (c.key == key) read_series = &c;
      if (read_series) costs = flow_time_costs(campaign_runs->runs[key], run_index);
    }
    DesignAdvice advice;
    try {
      advice = next_width(*s.fit, w, Q, err, spec->w_lo, spec->w_hi, spec->w_step, targets, costs ? &*costs : nullptr);
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
    const std::optional<std::size_t> extend = advice.next->extend_run;
    const RunRecord* extended = nullptr;
    if (extend) {
      const std::size_t i = run_index[*extend];
      extended = &campaign_runs->runs[key][i];
      d.job = extended_job(db, read_series->job_keys[i], *extended);
    } else {
      d.job = job_at(sj, advice.next->w);
    }
    d.k_err = advice.k_err_now;
    d.beta_err = advice.beta_err_now;
    d.k_err_after = advice.next->k_err_after;
    d.beta_err_after = advice.next->beta_err_after;
    d.flowing_points = static_cast<int>(w.size());
    std::ostringstream why;
    why << "w = " << num(advice.next->w) << " (replica " << d.job->config.replica;
    if (extended)
      why << ", more flow time: t = " << num(extended->end_time) << " -> " << num(d.job->config.run.min_time);
    why << "): k_err " << num(advice.k_err_now)
        << " -> " << num(advice.next->k_err_after) << ", beta_err " << num(advice.beta_err_now) << " -> "
        << num(advice.next->beta_err_after) << " predicted, cost " << num(advice.next->relative_cost)
        << " x a run at the median Q";
    d.reason = why.str();
    out.push_back(std::move(d));
  }
  if (spec->lambda && !any_busy) {
    // every series decided (before or just now) and none busy: the lambda stage
    std::set<std::string> stopped_now;
    for (const PlanDecision& d : out)
      if (d.action == "stop") stopped_now.insert(d.series_key);
    bool all_decided = out.empty() || stopped_now.size() == out.size();
    for (const std::string& key : order) all_decided = all_decided && (past[key].stopped || stopped_now.count(key));
    if (all_decided) plan_lambda(db, *spec->lambda, fits, jobs, past, out);
  }
  return out;
}

}  // namespace beverloo
