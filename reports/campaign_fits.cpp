#include "campaign_fits.h"
#include "core/digest.h"

#include "engine/parameters.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/text_escape.h"
#include "orchestrator/sweep/sweep.h"
#include "series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;

std::string fmt(double v, int digits = 4) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

}  // namespace

std::string format_lambda(double lambda) { return std::isinf(lambda) ? "inf" : fmt(lambda); }

std::string fit_quality(const Series& s) {
  if (!s.fit) return "no fit";
  const double rel = s.fit->beta_err / std::fabs(s.fit->beta);
  if (!(rel <= kBetaDeterminedRelErr)) {
    char b[96];
    std::snprintf(b, sizeof b, "not determined: beta's error is %.0f %%", 100 * rel);
    return b;
  }
  double w_min = INFINITY;
  for (const auto& p : s.points)
    if (p.flowing()) w_min = std::min(w_min, p.w);
  if (s.fit->k < 0 || s.fit->k >= w_min) return "not determined: k outside [0, smallest w]";
  return "ok";
}

int Series::clogged_points() const {
  int n = 0;
  for (const auto& p : points) n += !p.flowing() && p.clogged > 0;
  return n;
}

namespace {
/// Sorts a crossover group's finite-lambda series and fits the sigmoid to their beta.
void fit_group(Crossover& g) {
  std::sort(g.finite.begin(), g.finite.end(), [](const Series* a, const Series* b) { return a->lambda < b->lambda; });
  std::vector<double> l, b, e;
  for (const Series* s : g.finite) {
    l.push_back(s->lambda);
    b.push_back(s->fit->beta);
    e.push_back(s->fit->beta_err);
  }
  try {
    g.fit = fit_crossover(g.dimension, l, b, e);
  } catch (const FitError& err) {
    g.message = err.what();
  }
  try {
    g.fit_free = fit_crossover_free_plateaus(l, b, e);
  } catch (const FitError& err) {
    g.message_free = err.what();
  }
}
}  // namespace

CampaignFits fit_campaign(db::Database& db) {
  CampaignFits out;
  db::Statement st = db.prepare(
      "SELECT j.key, j.job_json, r.Q, r.Q_err, r.clogged, r.status, coalesce(r.clog_time, -1), r.steps, r.dt FROM jobs j "
      "JOIN campaign_jobs c ON c.job_key = j.key JOIN results r ON r.job_key = j.key "
      "WHERE c.campaign_id = (SELECT max(id) FROM campaigns) ORDER BY c.point_index");
  std::map<std::string, std::size_t> index;
  std::map<std::string, std::map<double, std::vector<std::tuple<double, double, bool, bool>>>> raw;
  // per series, replica, w: (Q, Q_err) of a flowing job, for the run-to-run spread of the exponent
  std::map<std::string, std::map<int, std::map<double, std::pair<double, double>>>> by_replica;
  // per series and w: every run's time to its clog, or to its end (censored); and t_max
  std::map<std::string, std::map<double, std::vector<SurvivalObservation>>> survival;
  std::map<std::string, std::map<double, double>> t_max_of;
  std::vector<json> series_jobs;               // per series, for labels that tell them apart
  std::map<std::string, json> base_job_of;     // series key -> its job without zeta and mu
  while (st.step()) {
    json job = json::parse(st.get_text(1));
    const double w = job["w"].get<double>();
    json series_job = job;
    for (const char* k : {"w", "replica", "seed"}) series_job.erase(k);
    const std::string key = sha256_hex(series_job.dump());
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
      base_job_of[key] = base;
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
    raw[key][w].emplace_back(st.get_double(2), st.get_double(3), st.get_int(4) != 0, st.get_text(5) == "time_limit");
    if (st.get_int(4) == 0 && st.get_double(2) > 0 && st.get_double(3) > 0)
      by_replica[key][job.value("replica", 0)][w] = {st.get_double(2), st.get_double(3)};
    {
      const bool clogged = st.get_int(4) != 0;
      const double end = static_cast<double>(st.get_int(7)) * st.get_double(8);  // steps x dt: the run's end
      survival[key][w].push_back({clogged && st.get_double(6) >= 0 ? st.get_double(6) : end, clogged});
      t_max_of[key][w] = job.contains("run") ? job["run"].value("t_max", 0.0) : 0.0;
    }
  }
  {
    std::vector<std::string> labels;
    for (const Series& s : out.series) labels.push_back(s.label);
    disambiguate_labels(labels, series_jobs);
    for (std::size_t i = 0; i < labels.size(); ++i) out.series[i].label = labels[i];
  }
  for (Series& s : out.series) {
    for (const auto& [w, reps] : raw[s.key]) {
      SeriesPoint p;
      p.w = w;
      p.replicas = static_cast<int>(reps.size());
      double sw = 0, swq = 0;
      for (const auto& [Q, err, clogged, time_limited] : reps) {
        p.time_limited += time_limited;
        if (clogged) {
          ++p.clogged;
          continue;
        }
        if (Q > 0 && err > 0 && std::isfinite(Q) && std::isfinite(err)) {
          sw += 1 / (err * err);
          swq += Q / (err * err);
        } else {
          ++s.left_out;  // a rate without an error cannot be weighted: not a 0 +- 0 point
        }
      }
      if (sw > 0) {
        p.Q = swq / sw;
        p.Q_err = 1 / std::sqrt(sw);
      }
      if (sw > 0 || p.clogged > 0) s.points.push_back(p);
    }
    std::vector<double> w, Q, e;
    for (const auto& p : s.points)
      if (p.flowing()) {
        w.push_back(p.w);
        Q.push_back(p.Q);
        e.push_back(p.Q_err);
      }
    try {
      s.fit = fit_beverloo(w, Q, e);
    } catch (const FitError& err) {
      s.message = err.what();
    }
    // The run-to-run spread: each replica (seed) fitted alone where every one has the widths the
    // pooled fit used; the sample standard deviation of their betas, beside the fit's own error
    // (the pooled fit's error says how well one set of points fixes beta, not how far another
    // seed's set would move it).
    if (s.fit) {
      const auto& reps = by_replica[s.key];
      std::vector<double> betas;
      for (const auto& [replica, pts] : reps) {
        if (pts.size() != w.size()) continue;
        std::vector<double> rw, rq, re;
        for (const auto& [wr, qe] : pts) {
          rw.push_back(wr);
          rq.push_back(qe.first);
          re.push_back(qe.second);
        }
        try {
          betas.push_back(fit_beverloo(rw, rq, re).beta);
        } catch (const FitError&) {
        }
      }
      s.replica_fits = static_cast<int>(betas.size());
      if (betas.size() >= 2) {
        double mean = 0, ss = 0;
        for (double b : betas) mean += b / betas.size();
        for (double b : betas) ss += (b - mean) * (b - mean);
        s.beta_replica_spread = std::sqrt(ss / (betas.size() - 1));
      }
    }
    if (!s.rate_is_c0()) {
      bool any_clog = false;
      for (const auto& [wv, runs] : survival[s.key])
        for (const SurvivalObservation& o : runs) any_clog = any_clog || o.clogged;
      if (any_clog)
        for (const auto& [wv, runs] : survival[s.key]) s.clog_points.push_back({wv, t_max_of[s.key][wv], kaplan_meier(runs)});
    }
    if (!s.rate_is_c0()) {
      try {
        s.authors_fit = fit_beverloo_bounded(w, Q, BoundedFitOptions::authors());
      } catch (const FitError& err) {
        s.authors_message = err.what();
      }
    }
  }
  // crossover groups: series sharing everything but zeta/mu, with the same drag for finite lambda
  std::map<std::string, Crossover> groups;
  for (const Series& s : out.series) {
    if (!(s.zeta > 0) || s.drag_rate > 0 || s.drain) continue;  // lambda = 0 joins below as a limit
    std::string gkey = s.base_key + "|zeta=" + fmt(s.zeta, 12);
    if (s.mu_n) gkey += "|mu_n=" + fmt(*s.mu_n, 12);  // (absent for the text's model: keys as before)
    if (s.mu_t) gkey += "|mu_t=" + fmt(*s.mu_t, 12);
    Crossover& g = groups[gkey];
    g.key = sha256_hex(gkey);
    g.dimension = s.dimension;
    g.label = std::to_string(s.dimension) + "D " + s.stiffness + " zeta=" + fmt(s.zeta, 3) + " N=" + std::to_string(s.N);
    if (std::isinf(s.lambda))
      g.limit_inf = &s;
    else if (s.fit)
      g.finite.push_back(&s);
  }
  for (auto& [gkey, g] : groups) {
    const std::string zeta_part = gkey.substr(gkey.find("|zeta=") + 6);
    const double scale = std::stod(zeta_part.substr(0, zeta_part.find('|'))) * std::sqrt(10.0);
    for (const Series& s : out.series)  // lambda = 0 at the same dissipation scale (mu = 10 sqrt 10 s)
      if (s.zeta == 0 && s.base_key == gkey.substr(0, gkey.find('|')) &&
          std::fabs(s.mu / (10 * std::sqrt(10.0)) - scale) <= 1e-9 * scale)
        g.limit0 = &s;
    fit_group(g);
    out.crossovers.push_back(g);
  }
  // The authors' lambda axis (docs/authors-model.md): drag as a rate times the mass, and
  // lambda = drag_rate M(sigma_avg) / mu_t. Their Fig. 4 varies it along two branches, the drag
  // at a fixed friction and then the friction at a fixed drag (Matlab-process oop/paper.m, bVec
  // and vVec), and plots both as one beta(lambda): so a group is every rate-drag series with
  // friction sharing everything else (the form of the friction, mu_n, included). Its limits:
  // lambda = 0, the friction of its lowest-lambda series without drag; lambda = inf, the drag of
  // its highest-lambda series without friction (else any rate-drag series without friction).
  std::map<std::string, Crossover> by_rate_drag;
  for (const Series& s : out.series) {
    if (!(s.drag_rate > 0) || s.zeta != 0 || !(s.mu > 0) || s.drain) continue;
    const std::string gkey = s.base_key + "|rate_drag|mu_n=" + (s.mu_n ? fmt(*s.mu_n, 12) : "mu");
    Crossover& g = by_rate_drag[gkey];
    g.key = sha256_hex(gkey);
    g.dimension = s.dimension;
    if (s.fit) g.finite.push_back(&s);
  }
  for (auto& [gkey, g] : by_rate_drag) {
    const std::string base = gkey.substr(0, gkey.find('|'));
    const Series* lowest = nullptr;
    const Series* highest = nullptr;
    for (const Series* s : g.finite) {
      if (!lowest || s->lambda < lowest->lambda) lowest = s;
      if (!highest || s->lambda > highest->lambda) highest = s;
    }
    std::set<double> frictions, drags;
    for (const Series* s : g.finite) {
      frictions.insert(s->mu);
      drags.insert(s->drag_rate);
    }
    const Series* any_inf = nullptr;
    for (const Series& s : out.series) {
      if (s.base_key != base || s.drain) continue;
      if (lowest && s.zeta == 0 && s.drag_rate == 0 && s.mu == lowest->mu && s.mu_n == lowest->mu_n &&
          s.mu_t == lowest->mu_t)
        g.limit0 = &s;
      if (s.mu == 0 && s.zeta == 0 && s.drag_rate > 0) {
        if (highest && s.drag_rate == highest->drag_rate) g.limit_inf = &s;
        if (!any_inf) any_inf = &s;
      }
    }
    if (!g.limit_inf) g.limit_inf = any_inf;
    const Series* any = lowest ? lowest : g.limit0;
    g.label = std::to_string(any ? any->dimension : g.dimension) + "D " + (any ? any->stiffness : std::string()) +
              (frictions.size() == 1   ? " mu=" + fmt(*frictions.begin(), 4) + " (drag rate)"
               : drags.size() == 1     ? " drag_rate=" + fmt(*drags.begin(), 4) + " (mu varied)"
                                       : std::string(" (drag rate and mu varied)")) +
              (any ? " N=" + std::to_string(any->N) : std::string());
    fit_group(g);
    out.crossovers.push_back(g);
  }
  // groups that differ in something other than their label's fields say so, as series do
  std::vector<std::string> labels;
  std::vector<json> bases;
  for (const Crossover& g : out.crossovers) {
    const Series* any = !g.finite.empty() ? g.finite.front() : g.limit0 ? g.limit0 : g.limit_inf;
    labels.push_back(g.label);
    bases.push_back(any ? base_job_of[any->key] : json::object());
  }
  disambiguate_labels(labels, bases);
  for (std::size_t i = 0; i < labels.size(); ++i) out.crossovers[i].label = labels[i];
  add_experiment_series(db, out);
  return out;
}

namespace {
/// "beta", "k,beta", ...: the parameters of a bounded fit that ended on a bound ("" for none).
std::string bound_names(const BoundedBeverlooFit& f) {
  std::string out;
  for (const auto& [at, name] : {std::pair{f.C_at_bound, "C"}, {f.k_at_bound, "k"}, {f.beta_at_bound, "beta"}})
    if (at) {
      if (!out.empty()) out += ',';
      out += name;
    }
  return out;
}

void store_authors_fit(db::Statement& au, const Series& s) {
  au.bind(1, s.key);
  if (s.authors_fit) {
    const BeverlooFit& f = s.authors_fit->fit;
    au.bind(2, f.C).bind(3, f.C_err).bind(4, f.k).bind(5, f.k_err).bind(6, f.beta).bind(7, f.beta_err).bind(8, f.points)
        .bind(9, bound_names(*s.authors_fit)).bind_null(10);
  } else {
    for (int c = 2; c <= 9; ++c) au.bind_null(c);
    if (s.authors_message.empty()) au.bind_null(10); else au.bind(10, s.authors_message);
  }
  au.bind(11, s.replica_fits);
  if (std::isnan(s.beta_replica_spread)) au.bind_null(12); else au.bind(12, s.beta_replica_spread);
  au.run();
}
}  // namespace

void store_fits(db::Database& db, const CampaignFits& fits) {
  db::Transaction tx(db);
  db.exec("DELETE FROM series_points; DELETE FROM beverloo_fit_results; DELETE FROM crossover_fit_results; "
          "DELETE FROM experiment_fit_results; DELETE FROM clog_survival;");
  db::Statement cs = db.prepare(
      "INSERT INTO clog_survival (series_key, label, w, runs, clogs, t_max, p_clog, p_clog_err, median_time, km_time, "
      "km_survival, km_survival_err) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)");
  db::Statement ex = db.prepare(
      "INSERT INTO experiment_fit_results (series_id, label, points, C, C_err, k, k_err, beta, beta_err, chi2_red, message) "
      "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)");
  db::Statement ins = db.prepare(
      "INSERT INTO beverloo_fit_results (series_key, label, dimension, N, E_sp, zeta, mu, lambda, theta_w_left_deg, "
      "theta_w_right_deg, points, clogged_points, C, C_err, k, k_err, beta, beta_err, chi2_red, message, model, n_v, "
      "K_a, K_l, K_b, E_c) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, "
      "?20, ?21, ?22, ?23, ?24, ?25, ?26)");
  db::Statement pt = db.prepare(
      "INSERT INTO series_points (series_key, w, Q, Q_err, replicas, clogged) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  db::Statement au = db.prepare(
      "UPDATE beverloo_fit_results SET authors_C = ?2, authors_C_err = ?3, authors_k = ?4, authors_k_err = ?5, "
      "authors_beta = ?6, authors_beta_err = ?7, authors_points = ?8, authors_at_bound = ?9, authors_message = ?10, "
      "replica_fits = ?11, beta_replica_spread = ?12 WHERE series_key = ?1");
  for (const Series& s : fits.series) {
    int flowing = 0;
    for (const auto& p : s.points) flowing += p.flowing();
    if (!s.provenance.empty()) {  // an imported series: its own table (no job parameters)
      ex.bind(1, s.experiment_id).bind(2, s.label).bind(3, flowing);
      if (s.fit)
        ex.bind(4, s.fit->C).bind(5, s.fit->C_err).bind(6, s.fit->k).bind(7, s.fit->k_err).bind(8, s.fit->beta)
            .bind(9, s.fit->beta_err).bind(10, s.fit->chi2_red).bind_null(11);
      else {
        for (int c = 4; c <= 10; ++c) ex.bind_null(c);
        ex.bind(11, s.message);
      }
      ex.run();
      continue;
    }
    auto real_or_null = [&](int col, double v) {
      if (std::isnan(v)) ins.bind_null(col); else ins.bind(col, v);
    };
    ins.bind(1, s.key).bind(2, s.label).bind(3, s.dimension).bind(4, s.N).bind(6, s.zeta).bind(7, s.mu);
    real_or_null(5, s.E_sp);
    ins.bind(21, s.model);
    if (s.is_dp()) ins.bind(22, s.n_v); else ins.bind_null(22);
    real_or_null(23, s.K_a);
    real_or_null(24, s.K_l);
    real_or_null(25, s.K_b);
    real_or_null(26, s.E_c);
    real_or_null(8, s.lambda);
    ins.bind(9, s.theta_left).bind(10, s.theta_right).bind(11, flowing).bind(12, s.clogged_points());
    if (s.fit) {
      ins.bind(13, s.fit->C).bind(14, s.fit->C_err).bind(15, s.fit->k).bind(16, s.fit->k_err).bind(17, s.fit->beta)
          .bind(18, s.fit->beta_err).bind(19, s.fit->chi2_red).bind_null(20);
    } else {
      for (int c = 13; c <= 19; ++c) ins.bind_null(c);
      ins.bind(20, s.message);
    }
    ins.run();
    store_authors_fit(au, s);
    for (const Series::ClogPoint& c : s.clog_points) {
      const double horizon = c.t_max > 0 ? c.t_max : INFINITY;
      cs.bind(1, s.key).bind(2, s.label).bind(3, c.w).bind(4, c.km.runs).bind(5, c.km.clogs).bind(6, c.t_max)
          .bind(7, 1 - c.km.at(horizon)).bind(8, c.km.err_at(horizon));
      if (std::isnan(c.km.median())) cs.bind_null(9); else cs.bind(9, c.km.median());
      cs.bind(10, json(c.km.time).dump()).bind(11, json(c.km.survival).dump()).bind(12, json(c.km.survival_err).dump()).run();
    }
    for (const auto& p : s.points)
      pt.bind(1, s.key).bind(2, p.w).bind(3, p.Q).bind(4, p.Q_err).bind(5, p.replicas).bind(6, p.clogged).run();
  }
  db::Statement cx = db.prepare(
      "INSERT INTO crossover_fit_results (group_key, label, dimension, points, lambda_c, lambda_c_err, b, b_err, chi2_red, "
      "beta_lambda0, beta_lambda0_err, beta_inf, beta_inf_err, message) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, "
      "?11, ?12, ?13, ?14)");
  db::Statement fr = db.prepare(
      "UPDATE crossover_fit_results SET free_lambda_c = ?2, free_lambda_c_err = ?3, free_b = ?4, free_b_err = ?5, "
      "free_beta_lambda0 = ?6, free_beta_lambda0_err = ?7, free_beta_inf = ?8, free_beta_inf_err = ?9, free_chi2_red = ?10, "
      "free_message = ?11 WHERE group_key = ?1");
  for (const Crossover& g : fits.crossovers) {
    cx.bind(1, g.key).bind(2, g.label).bind(3, g.dimension).bind(4, static_cast<int>(g.finite.size()));
    if (g.fit)
      cx.bind(5, g.fit->lambda_c).bind(6, g.fit->lambda_c_err).bind(7, g.fit->b).bind(8, g.fit->b_err).bind(9, g.fit->chi2_red);
    else
      for (int c = 5; c <= 9; ++c) cx.bind_null(c);
    auto limit = [&](int col, const Series* s) {
      if (s && s->fit) cx.bind(col, s->fit->beta).bind(col + 1, s->fit->beta_err);
      else cx.bind_null(col).bind_null(col + 1);
    };
    limit(10, g.limit0);
    limit(12, g.limit_inf);
    if (g.fit) cx.bind_null(14); else cx.bind(14, g.message);
    cx.run();
    fr.bind(1, g.key);
    if (g.fit_free) {
      const CrossoverFit& f = *g.fit_free;
      fr.bind(2, f.lambda_c).bind(3, f.lambda_c_err).bind(4, f.b).bind(5, f.b_err).bind(6, f.beta_0).bind(7, f.beta_0_err)
          .bind(8, f.beta_inf).bind(9, f.beta_inf_err).bind(10, f.chi2_red).bind_null(11);
    } else {
      for (int c = 2; c <= 10; ++c) fr.bind_null(c);
      fr.bind(11, g.message_free);
    }
    fr.run();
  }
  tx.commit();
}

void write_fit_tables(const CampaignFits& fits, const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::ostringstream csv, md, xcsv, xmd;
  csv << "label,model,dimension,N,E_sp,K_l,K_b,E_c,zeta,mu,lambda,points,clogged_points,C,C_err,k,k_err,beta,beta_err,"
         "chi2_red,message\n";
  md << "| series | points | clogged | C | k | beta | chi2_red |\n|---|---|---|---|---|---|---|\n";
  for (const Series& s : fits.series) {
    int flowing = 0;
    for (const auto& p : s.points) flowing += p.flowing();
    csv << csv_field(s.label) << ',' << csv_field(s.model) << ',' << s.dimension << ',' << s.N << ',' << fmt(s.E_sp, 10) << ','
        << fmt(s.K_l, 10) << ',' << fmt(s.K_b, 10) << ',' << fmt(s.E_c, 10) << ',' << fmt(s.zeta, 10) << ','
        << fmt(s.mu, 10) << ',' << format_lambda(s.lambda) << ',' << flowing << ',' << s.clogged_points() << ',';
    if (s.fit)
      csv << fmt(s.fit->C, 8) << ',' << fmt(s.fit->C_err, 4) << ',' << fmt(s.fit->k, 8) << ',' << fmt(s.fit->k_err, 4) << ','
          << fmt(s.fit->beta, 8) << ',' << fmt(s.fit->beta_err, 4) << ',' << fmt(s.fit->chi2_red, 4) << ",\n";
    else
      csv << ",,,,,,," << csv_field(s.message) << "\n";
    md << "| " << markdown_cell(s.label) << " | " << flowing << " | " << s.clogged_points() << " | ";
    if (s.fit)
      md << fmt(s.fit->C) << " ± " << fmt(s.fit->C_err, 2) << " | " << fmt(s.fit->k) << " ± " << fmt(s.fit->k_err, 2) << " | "
         << fmt(s.fit->beta) << " ± " << fmt(s.fit->beta_err, 2) << " | " << fmt(s.fit->chi2_red, 3) << " |\n";
    else
      md << "no fit: " << markdown_cell(s.message) << " | | | |\n";
  }
  xcsv << "label,dimension,points,lambda_c,lambda_c_err,b,b_err,chi2_red,beta_lambda0,beta_inf,message\n";
  xmd << "| group | points | lambda_c | b | chi2_red | beta(lambda=0) | beta(lambda=inf) |\n|---|---|---|---|---|---|---|\n";
  for (const Crossover& g : fits.crossovers) {
    const std::string b0 = g.limit0 && g.limit0->fit ? fmt(g.limit0->fit->beta) : "";
    const std::string binf = g.limit_inf && g.limit_inf->fit ? fmt(g.limit_inf->fit->beta) : "";
    xcsv << csv_field(g.label) << ',' << g.dimension << ',' << g.finite.size() << ',';
    if (g.fit)
      xcsv << fmt(g.fit->lambda_c, 8) << ',' << fmt(g.fit->lambda_c_err, 4) << ',' << fmt(g.fit->b, 8) << ','
           << fmt(g.fit->b_err, 4) << ',' << fmt(g.fit->chi2_red, 4);
    else
      xcsv << ",,,,";
    xcsv << ',' << b0 << ',' << binf << ',' << csv_field(g.message) << "\n";
    xmd << "| " << markdown_cell(g.label) << " | " << g.finite.size() << " | ";
    if (g.fit)
      xmd << fmt(g.fit->lambda_c) << " ± " << fmt(g.fit->lambda_c_err, 2) << " | " << fmt(g.fit->b) << " ± "
          << fmt(g.fit->b_err, 2) << " | " << fmt(g.fit->chi2_red, 3);
    else
      xmd << "no fit: " << markdown_cell(g.message) << " | | ";
    xmd << " | " << b0 << " | " << binf << " |\n";
  }
  // both ways side by side: the default free fit and the authors' bounded one; the crossover
  // with the paper's fixed plateaus and with free ones
  std::ostringstream bcsv, bmd, fcsv, fmd;
  bcsv << "label,lambda,beta,beta_err,replica_fits,beta_replica_spread,k,k_err,C,C_err,authors_points,authors_beta,authors_beta_err,authors_k,authors_k_err,"
          "authors_C,authors_C_err,authors_at_bound,authors_message\n";
  bmd << "| series | beta (free) | spread of beta over replicas | beta (authors' way) | k (free) | k (authors' way) | at a "
         "bound |\n|---|---|---|---|---|---|---|\n";
  for (const Series& s : fits.series) {
    if (s.rate_is_c0()) continue;
    bcsv << csv_field(s.label) << ',' << format_lambda(s.lambda) << ',';
    if (s.fit)
      bcsv << fmt(s.fit->beta, 8) << ',' << fmt(s.fit->beta_err, 4) << ',' << s.replica_fits << ','
           << (std::isnan(s.beta_replica_spread) ? std::string() : fmt(s.beta_replica_spread, 4)) << ',' << fmt(s.fit->k, 8)
           << ',' << fmt(s.fit->k_err, 4) << ',' << fmt(s.fit->C, 8) << ',' << fmt(s.fit->C_err, 4) << ',';
    else
      bcsv << ",,,,,,,,";
    if (s.authors_fit) {
      const BeverlooFit& a = s.authors_fit->fit;
      bcsv << a.points << ',' << fmt(a.beta, 8) << ',' << fmt(a.beta_err, 4) << ',' << fmt(a.k, 8) << ',' << fmt(a.k_err, 4)
           << ',' << fmt(a.C, 8) << ',' << fmt(a.C_err, 4) << ',' << csv_field(bound_names(*s.authors_fit)) << ",\n";
    } else {
      bcsv << ",,,,,,,," << csv_field(s.authors_message) << "\n";
    }
    auto pm = [](double v, double e) { return fmt(v) + " ± " + fmt(e, 2); };
    const std::string spread = std::isnan(s.beta_replica_spread)
                                   ? std::string("-")
                                   : fmt(s.beta_replica_spread, 2) + " (" + std::to_string(s.replica_fits) + " replicas)";
    bmd << "| " << markdown_cell(s.label) << " | " << (s.fit ? pm(s.fit->beta, s.fit->beta_err) : "no fit") << " | " << spread
        << " | " << (s.authors_fit ? pm(s.authors_fit->fit.beta, s.authors_fit->fit.beta_err) : "no fit") << " | "
        << (s.fit ? pm(s.fit->k, s.fit->k_err) : "") << " | "
        << (s.authors_fit ? pm(s.authors_fit->fit.k, s.authors_fit->fit.k_err) : "") << " | "
        << (s.authors_fit ? bound_names(*s.authors_fit) : markdown_cell(s.authors_message)) << " |\n";
  }
  fcsv << "label,points,lambda_c,lambda_c_err,b,b_err,chi2_red,free_lambda_c,free_lambda_c_err,free_b,free_b_err,"
          "free_beta_lambda0,free_beta_lambda0_err,free_beta_inf,free_beta_inf_err,free_chi2_red,free_message\n";
  fmd << "| group | lambda_c (plateaus 1/2, 3/2 from d) | chi2_red | lambda_c (plateaus free) | b | beta(0) fitted | "
         "beta(inf) fitted | chi2_red | beta(0), beta(inf) measured |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Crossover& g : fits.crossovers) {
    fcsv << csv_field(g.label) << ',' << g.finite.size() << ',';
    if (g.fit)
      fcsv << fmt(g.fit->lambda_c, 8) << ',' << fmt(g.fit->lambda_c_err, 4) << ',' << fmt(g.fit->b, 8) << ','
           << fmt(g.fit->b_err, 4) << ',' << fmt(g.fit->chi2_red, 4) << ',';
    else
      fcsv << ",,,,,";
    if (g.fit_free) {
      const CrossoverFit& f = *g.fit_free;
      fcsv << fmt(f.lambda_c, 8) << ',' << fmt(f.lambda_c_err, 4) << ',' << fmt(f.b, 8) << ',' << fmt(f.b_err, 4) << ','
           << fmt(f.beta_0, 8) << ',' << fmt(f.beta_0_err, 4) << ',' << fmt(f.beta_inf, 8) << ',' << fmt(f.beta_inf_err, 4)
           << ',' << fmt(f.chi2_red, 4) << ",\n";
    } else {
      fcsv << ",,,,,,,,," << csv_field(g.message_free) << "\n";
    }
    auto measured = [](const Series* s) { return s && s->fit ? fmt(s->fit->beta) + " ± " + fmt(s->fit->beta_err, 2) : std::string("-"); };
    fmd << "| " << markdown_cell(g.label) << " | "
        << (g.fit ? fmt(g.fit->lambda_c) + " ± " + fmt(g.fit->lambda_c_err, 2) + " | " + fmt(g.fit->chi2_red, 3)
                  : "no fit | ")
        << " | ";
    if (g.fit_free) {
      const CrossoverFit& f = *g.fit_free;
      fmd << fmt(f.lambda_c) << " ± " << fmt(f.lambda_c_err, 2) << " | " << fmt(f.b) << " ± " << fmt(f.b_err, 2) << " | "
          << fmt(f.beta_0) << " ± " << fmt(f.beta_0_err, 2) << " | " << fmt(f.beta_inf) << " ± " << fmt(f.beta_inf_err, 2)
          << " | " << fmt(f.chi2_red, 3);
    } else {
      fmd << "no fit: " << markdown_cell(g.message_free) << " | | | | ";
    }
    fmd << " | " << measured(g.limit0) << ", " << measured(g.limit_inf) << " |\n";
  }
  // clogging: per series and w with the Kaplan-Meier probability to clog within t_max
  std::ostringstream ccsv, cmd;
  ccsv << "label,w,runs,clogs,t_max,p_clog,p_clog_err,median_time\n";
  cmd << "| series | w | runs | clogs | P(clog within t_max) | median time to clog [t0] |\n|---|---|---|---|---|---|\n";
  for (const Series& s : fits.series)
    for (const Series::ClogPoint& c : s.clog_points) {
      const double horizon = c.t_max > 0 ? c.t_max : INFINITY, median = c.km.median();
      ccsv << csv_field(s.label) << ',' << fmt(c.w, 10) << ',' << c.km.runs << ',' << c.km.clogs << ',' << fmt(c.t_max, 10) << ','
           << fmt(1 - c.km.at(horizon), 6) << ',' << fmt(c.km.err_at(horizon), 4) << ','
           << (std::isnan(median) ? std::string() : fmt(median, 6)) << "\n";
      cmd << "| " << markdown_cell(s.label) << " | " << fmt(c.w) << " | " << c.km.runs << " | " << c.km.clogs << " | "
          << fmt(1 - c.km.at(horizon), 3) << " ± " << fmt(c.km.err_at(horizon), 2) << " (t_max " << fmt(c.t_max) << ") | "
          << (std::isnan(median) ? std::string("beyond the runs") : fmt(median, 3)) << " |\n";
    }
  const std::filesystem::path d(dir);
  write_text_atomically((d / "clog_statistics.csv").string(), ccsv.str());
  write_text_atomically((d / "clog_statistics.md").string(), cmd.str());
  write_text_atomically((d / "beverloo_fits_both_ways.csv").string(), bcsv.str());
  write_text_atomically((d / "beverloo_fits_both_ways.md").string(), bmd.str());
  write_text_atomically((d / "crossover_fits_both_ways.csv").string(), fcsv.str());
  write_text_atomically((d / "crossover_fits_both_ways.md").string(), fmd.str());
  write_text_atomically((d / "beverloo_fits.csv").string(), csv.str());
  write_text_atomically((d / "beverloo_fits.md").string(), md.str());
  write_text_atomically((d / "crossover_fits.csv").string(), xcsv.str());
  write_text_atomically((d / "crossover_fits.md").string(), xmd.str());
}

}  // namespace beverloo
