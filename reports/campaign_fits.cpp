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
#include "campaign_runs.h"
#include "crossover_groups.h"
#include "series_fits.h"
#include "series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;

std::string fmt(double v, int digits = 4) { return table_number(v, digits); }

}  // namespace

std::string table_number(double v, int digits) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string format_lambda(double lambda) { return std::isinf(lambda) ? "inf" : fmt(lambda); }

std::string fit_quality(const Series& s) {
  if (!s.fit) return "no fit";
  const double rel = s.fit->beta_err / std::fabs(s.fit->beta);
  if (!(rel <= kBetaDeterminedRelErr)) {
    char b[96];
    std::snprintf(b, sizeof b, "not determined: beta's error is %.0f %%", 100 * rel);
    return b;
  }
  if (follows_no_beverloo_law(s)) {
    char b[128];
    std::snprintf(b, sizeof b, "not determined: k = %.3g +- %.2g, ", s.fit->k, s.fit->k_err);
    return b + no_beverloo_law_rule().substr(2);  // "outside [0, ...": k is named with its value
  }
  return "ok";
}

bool follows_no_beverloo_law(const Series& s) {
  if (!s.fit) return false;
  double w_min = INFINITY;
  for (const auto& p : s.points)
    if (p.flowing()) w_min = std::min(w_min, p.w);
  // a k within its errors of the range is a Beverloo law whose k the widths do not pin: its
  // beta's error (correlated with k's) already says how little it is worth. A k_err that is
  // not a number (a fit without errors) gives no tolerance.
  const double tolerance = std::isfinite(s.fit->k_err) ? kBeverlooLawKSigmas * s.fit->k_err : 0.0;
  return s.fit->k < -tolerance || s.fit->k >= w_min + tolerance;
}

std::string no_beverloo_law_rule() {
  char b[80];
  std::snprintf(b, sizeof b, "k outside [0, smallest w] by more than %g errors", kBeverlooLawKSigmas);
  return b;
}

int Series::clogged_points() const {
  int n = 0;
  for (const auto& p : points) n += !p.flowing() && p.clogged > 0;
  return n;
}

namespace {
/// The series of a campaign fitted, the imported experiments appended if asked, and then the
/// beta(lambda) groups: last, because a group points into `series` (appending after it could
/// move the vector and leave the pointers dangling). Experiments never join a group.
CampaignFits fitted(db::Database& db, const CampaignScope& scope, FlowRate rate, bool with_experiments) {
  CampaignRuns runs = read_campaign_runs(db, scope, rate);
  CampaignFits out;
  out.series = std::move(runs.series);
  for (Series& s : out.series) fit_series(s, runs.runs[s.key]);
  if (with_experiments) add_experiment_series(db, out);
  out.crossovers = crossover_groups(out.series, runs.base_job_of);
  return out;
}
}  // namespace

CampaignFits fit_campaign(db::Database& db, FlowRate rate, const CampaignScope& scope) {
  return fitted(db, scope, rate, rate == FlowRate::Q);  // the experiments have no Q'
}

CampaignFits fit_campaign_with_crossovers(db::Database& db, std::int64_t campaign, FlowRate rate) {
  return fitted(db, campaign < 0 ? CampaignScope::latest() : CampaignScope::one(campaign), rate, false);
}

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

namespace {
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
  for (const auto& [col, fit] : {std::pair{13, &s.authors_fixed_lo}, std::pair{16, &s.authors_fixed_hi}}) {
    if (*fit)
      au.bind(col, (*fit)->k).bind(col + 1, (*fit)->k_err).bind(col + 2, (*fit)->C);
    else
      au.bind_null(col).bind_null(col + 1).bind_null(col + 2);
  }
  int col = 19;
  for (double spread : {s.k_replica_spread, s.k_at_beta_lo_replica_spread, s.k_at_beta_hi_replica_spread}) {
    if (std::isnan(spread)) au.bind_null(col); else au.bind(col, spread);
    ++col;
  }
  if (s.authors_fit) au.bind(22, s.authors_fit->fit.folded_points); else au.bind_null(22);
  col = 23;
  for (const auto* fit : {&s.authors_fixed_lo, &s.authors_fixed_hi}) {
    if (*fit) au.bind(col, (*fit)->folded_points); else au.bind_null(col);
    ++col;
  }
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
      "replica_fits = ?11, beta_replica_spread = ?12, authors_k_at_beta_lo = ?13, authors_k_at_beta_lo_err = ?14, "
      "authors_C_at_beta_lo = ?15, authors_k_at_beta_hi = ?16, authors_k_at_beta_hi_err = ?17, authors_C_at_beta_hi = ?18, "
      "k_replica_spread = ?19, authors_k_at_beta_lo_replica_spread = ?20, authors_k_at_beta_hi_replica_spread = ?21, "
      "authors_folded_points = ?22, authors_k_at_beta_lo_folded_points = ?23, authors_k_at_beta_hi_folded_points = ?24 "
      "WHERE series_key = ?1");
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
  db::Statement sp = db.prepare(
      "UPDATE crossover_fit_results SET replica_fits = ?2, log10_lambda_c_replica_spread = ?3, b_replica_spread = ?4, "
      "free_replica_fits = ?5, free_log10_lambda_c_replica_spread = ?6, free_b_replica_spread = ?7 WHERE group_key = ?1");
  db::Statement cr = db.prepare(
      "UPDATE crossover_fit_results SET crossing_lambda = ?2, crossing_lambda_lo = ?3, crossing_lambda_hi = ?4, "
      "crossing_log10_err = ?5, crossing_log10_replica_spread = ?6, crossing_replicas = ?7, "
      "crossing_log10_interpolation = ?8, crossing_log10_sigma = ?9 WHERE group_key = ?1");
  for (const Crossover& g : fits.crossovers) {
    cx.bind(1, g.key).bind(2, g.label).bind(3, g.dimension).bind(4, g.fitted_points());
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
    sp.bind(1, g.key);
    for (auto [col, spread] : {std::pair{2, &g.spread}, std::pair{5, &g.spread_free}}) {
      sp.bind(col, spread->replicas);
      for (auto [c, v] : {std::pair{col + 1, spread->log10_lambda_c}, std::pair{col + 2, spread->b}})
        if (std::isnan(v)) sp.bind_null(c); else sp.bind(c, v);
    }
    sp.run();
    if (const std::optional<MidpointCrossing> m = crossing_of_d_minus_1(g)) {
      cr.bind(1, g.key).bind(2, std::pow(10.0, m->log10_lambda)).bind(3, m->lambda_lo).bind(4, m->lambda_hi).bind(5, m->sigma);
      for (auto [c, v] : {std::pair{6, m->spread}, std::pair{8, m->interpolation}})
        if (std::isnan(v)) cr.bind_null(c); else cr.bind(c, v);
      cr.bind(7, m->replicas).bind(9, m->verdict_sigma()).run();
    }
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
    xcsv << csv_field(g.label) << ',' << g.dimension << ',' << g.fitted_points() << ',';
    if (g.fit)
      xcsv << fmt(g.fit->lambda_c, 8) << ',' << fmt(g.fit->lambda_c_err, 4) << ',' << fmt(g.fit->b, 8) << ','
           << fmt(g.fit->b_err, 4) << ',' << fmt(g.fit->chi2_red, 4);
    else
      xcsv << ",,,,";
    xcsv << ',' << b0 << ',' << binf << ',' << csv_field(g.message) << "\n";
    xmd << "| " << markdown_cell(g.label) << " | " << g.fitted_points() << " | ";
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
          "authors_C,authors_C_err,authors_at_bound,authors_message,authors_k_at_beta_lo,authors_k_at_beta_lo_err,"
          "authors_k_at_beta_hi,authors_k_at_beta_hi_err,k_replica_spread,authors_k_at_beta_lo_replica_spread,"
          "authors_k_at_beta_hi_replica_spread,authors_folded_points,authors_k_at_beta_lo_folded_points,"
          "authors_k_at_beta_hi_folded_points\n";
  bmd << "| series | beta (free) | spread of beta over replicas | beta (authors' way) | k (free) | k (authors' way) | at a "
         "bound | k at beta = d - 3/2; d - 1/2 (authors' way) |\n|---|---|---|---|---|---|---|---|\n";
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
           << ',' << fmt(a.C, 8) << ',' << fmt(a.C_err, 4) << ',' << csv_field(bound_names(*s.authors_fit)) << ",";
    } else {
      bcsv << ",,,,,,,," << csv_field(s.authors_message);
    }
    for (const auto* fixed : {&s.authors_fixed_lo, &s.authors_fixed_hi})
      bcsv << ',' << (*fixed ? fmt((*fixed)->k, 8) : "") << ',' << (*fixed ? fmt((*fixed)->k_err, 4) : "");
    for (double spread : {s.k_replica_spread, s.k_at_beta_lo_replica_spread, s.k_at_beta_hi_replica_spread})
      bcsv << ',' << (std::isnan(spread) ? std::string() : fmt(spread, 4));
    bcsv << ',' << (s.authors_fit ? std::to_string(s.authors_fit->fit.folded_points) : "");
    for (const auto* fixed : {&s.authors_fixed_lo, &s.authors_fixed_hi})
      bcsv << ',' << (*fixed ? std::to_string((*fixed)->folded_points) : "");
    bcsv << "\n";
    auto pm = [](double v, double e) { return fmt(v) + " ± " + fmt(e, 2); };
    // a k with its spread over replicas where there is one
    auto pm_spread = [&pm](double v, double e, double spread) {
      return pm(v, e) + (std::isnan(spread) ? std::string() : " (spread " + fmt(spread, 2) + ")");
    };
    // a k of the authors' |w - k| fits that lies above some of its widths says so
    auto folded = [](const BeverlooFit& f) {
      const std::string note = folded_widths_note(f);
      return note.empty() ? note : " (" + markdown_cell(note) + ")";
    };
    const std::string spread = std::isnan(s.beta_replica_spread)
                                   ? std::string("-")
                                   : fmt(s.beta_replica_spread, 2) + " (" + std::to_string(s.replica_fits) + " replicas)";
    bmd << "| " << markdown_cell(s.label) << " | " << (s.fit ? pm(s.fit->beta, s.fit->beta_err) : "no fit") << " | " << spread
        << " | " << (s.authors_fit ? pm(s.authors_fit->fit.beta, s.authors_fit->fit.beta_err) : "no fit") << " | "
        << (s.fit ? pm_spread(s.fit->k, s.fit->k_err, s.k_replica_spread) : "") << " | "
        << (s.authors_fit ? pm(s.authors_fit->fit.k, s.authors_fit->fit.k_err) + folded(s.authors_fit->fit) : "") << " | "
        << (s.authors_fit ? bound_names(*s.authors_fit) : markdown_cell(s.authors_message)) << " | "
        << (s.authors_fixed_lo ? pm_spread(s.authors_fixed_lo->k, s.authors_fixed_lo->k_err, s.k_at_beta_lo_replica_spread) +
                                     folded(*s.authors_fixed_lo)
                               : "-")
        << "; "
        << (s.authors_fixed_hi ? pm_spread(s.authors_fixed_hi->k, s.authors_fixed_hi->k_err, s.k_at_beta_hi_replica_spread) +
                                     folded(*s.authors_fixed_hi)
                               : "-")
        << " |\n";
  }
  fcsv << "label,points,lambda_c,lambda_c_err,b,b_err,chi2_red,free_lambda_c,free_lambda_c_err,free_b,free_b_err,"
          "free_beta_lambda0,free_beta_lambda0_err,free_beta_inf,free_beta_inf_err,free_chi2_red,free_message,"
          "replica_fits,log10_lambda_c_replica_spread,b_replica_spread,free_replica_fits,"
          "free_log10_lambda_c_replica_spread,free_b_replica_spread,crossing_lambda,crossing_lambda_lo,crossing_lambda_hi,"
          "crossing_log10_err,crossing_log10_replica_spread,crossing_replicas,crossing_log10_interpolation,"
          "crossing_log10_sigma\n";
  fmd << "| group | lambda_c (plateaus 1/2, 3/2 from d) | chi2_red | lambda_c (plateaus free) | b | beta(0) fitted | "
         "beta(inf) fitted | chi2_red | beta(0), beta(inf) measured | beta = d - 1 at (no sigmoid) |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Crossover& g : fits.crossovers) {
    fcsv << csv_field(g.label) << ',' << g.fitted_points() << ',';
    if (g.fit)
      fcsv << fmt(g.fit->lambda_c, 8) << ',' << fmt(g.fit->lambda_c_err, 4) << ',' << fmt(g.fit->b, 8) << ','
           << fmt(g.fit->b_err, 4) << ',' << fmt(g.fit->chi2_red, 4) << ',';
    else
      fcsv << ",,,,,";
    if (g.fit_free) {
      const CrossoverFit& f = *g.fit_free;
      fcsv << fmt(f.lambda_c, 8) << ',' << fmt(f.lambda_c_err, 4) << ',' << fmt(f.b, 8) << ',' << fmt(f.b_err, 4) << ','
           << fmt(f.beta_0, 8) << ',' << fmt(f.beta_0_err, 4) << ',' << fmt(f.beta_inf, 8) << ',' << fmt(f.beta_inf_err, 4)
           << ',' << fmt(f.chi2_red, 4) << ",";
    } else {
      fcsv << ",,,,,,,,," << csv_field(g.message_free);
    }
    for (const Crossover::ReplicaSpread* r : {&g.spread, &g.spread_free})
      fcsv << ',' << r->replicas << ',' << fmt(r->log10_lambda_c, 4) << ',' << fmt(r->b, 4);
    const std::optional<MidpointCrossing> crossing = crossing_of_d_minus_1(g);
    if (crossing)
      fcsv << ',' << fmt(std::pow(10.0, crossing->log10_lambda), 8) << ',' << fmt(crossing->lambda_lo, 8) << ','
           << fmt(crossing->lambda_hi, 8) << ',' << fmt(crossing->sigma, 4) << ',' << fmt(crossing->spread, 4) << ','
           << crossing->replicas << ',' << fmt(crossing->interpolation, 4) << ',' << fmt(crossing->verdict_sigma(), 4);
    else
      fcsv << ",,,,,,,,";
    fcsv << "\n";
    // lambda_c with its spread over replicas in decades (log10), where there is one
    auto spread_text = [](const Crossover::ReplicaSpread& r) {
      const std::string phrase = lambda_c_spread_phrase(r);
      return phrase.empty() ? phrase : " (" + phrase + ")";
    };
    auto measured = [](const Series* s) { return s && s->fit ? fmt(s->fit->beta) + " ± " + fmt(s->fit->beta_err, 2) : std::string("-"); };
    fmd << "| " << markdown_cell(g.label) << " | "
        << (g.fit ? fmt(g.fit->lambda_c) + " ± " + fmt(g.fit->lambda_c_err, 2) + spread_text(g.spread) + " | " +
                        fmt(g.fit->chi2_red, 3)
                  : "no fit: " + markdown_cell(g.message) + " | ")
        << " | ";
    if (g.fit_free) {
      const CrossoverFit& f = *g.fit_free;
      fmd << fmt(f.lambda_c) << " ± " << fmt(f.lambda_c_err, 2) << spread_text(g.spread_free) << " | " << fmt(f.b) << " ± "
          << fmt(f.b_err, 2) << " | "
          << fmt(f.beta_0) << " ± " << fmt(f.beta_0_err, 2) << " | " << fmt(f.beta_inf) << " ± " << fmt(f.beta_inf_err, 2)
          << " | " << fmt(f.chi2_red, 3);
    } else {
      fmd << "no fit: " << markdown_cell(g.message_free) << " | | | | ";
    }
    fmd << " | " << measured(g.limit0) << ", " << measured(g.limit_inf) << " | "
        << (crossing ? fmt(std::pow(10.0, crossing->log10_lambda)) + " (" + fmt(crossing->lambda_lo) + " .. " +
                           fmt(crossing->lambda_hi) + "; ± " + fmt(crossing->verdict_sigma(), 2) + " in log10)"
                     : std::string("-"))
        << " |\n";
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
