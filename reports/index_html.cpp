#include "index_html.h"

#include <cmath>
#include <sstream>

#include "core/text_escape.h"
#include "engine/protocol/run_result.h"
#include "orchestrator/campaign/job_speed.h"
#include "orchestrator/campaign/store.h"
#include "reports/crossover_groups.h"
#include "reports/number_format.h"
#include "reports/paper_claims.h"

namespace beverloo {
namespace {

std::string pm(double v, double e) { return format_with_error(v, e, " &plusmn; "); }

void run_summary(std::ostringstream& html, db::Database& db, const CampaignScope& scope) {
  db::Statement c = db.prepare(scope.latest_in_scope_sql());
  const bool have = c.step();
  html << "<h1>beverloo report: " << html_escape(have ? c.get_text(1) : std::string("(no campaign)")) << "</h1>\n";
  if (scope.is_all())
    html << "<p>The jobs of " << html_escape(scope.describe(db)) << " in this directory, each once (`beverloo report "
            "--campaign all`); the heading names the latest.</p>\n";
  html << "<p class=units>Units: lengths in sigma_avg (the mean particle diameter), times in "
          "t0 = (sigma_avg / g)<sup>1/2</sup>, velocities in sigma_avg / t0, flow rates Q in "
          "Q_0 = sigma_avg<sup>d</sup> / t0 (area per time in 2D, volume per time in 3D). "
          "lambda = zeta / mu is dimensionless.</p>\n";
  html << "<h2>Run summary</h2>\n<table><tr><th>jobs by state</th><th>count</th><th>meaning</th></tr>\n";
  db::Statement s = db.prepare(
      "SELECT j.state, count(*) FROM jobs j JOIN (" + scope.jobs_in_scope_sql() + ") cj ON cj.job_key = j.key "
      "GROUP BY j.state ORDER BY j.state");
  while (s.step())
    html << "<tr><td>" << s.get_text(0) << "</td><td>" << s.get_int(1) << "</td><td>" << job_state_meaning(s.get_text(0))
         << "</td></tr>\n";
  html << "</table>\n<table><tr><th>how finished runs ended</th><th>count</th><th>meaning</th></tr>\n";
  db::Statement st = db.prepare(
      "SELECT r.status, count(*) FROM results r JOIN (" + scope.jobs_in_scope_sql() + ") cj ON cj.job_key = r.job_key "
      "GROUP BY 1 ORDER BY 1");
  while (st.step()) {
    const std::string status = st.get_text(0);
    const char* meaning = run_status_meaning(status);
    html << "<tr><td>" << html_escape(status) << "</td><td>" << st.get_int(1) << "</td><td>" << meaning << "</td></tr>\n";
  }
  html << "</table>\n<table><tr><th>failed attempts by class</th><th>count</th></tr>\n";
  db::Statement fcl = db.prepare(
      "SELECT a.failure_class, count(*) FROM attempts a JOIN (" + scope.jobs_in_scope_sql() + ") cj ON cj.job_key = a.job_key "
      "WHERE a.failure_class IS NOT NULL GROUP BY 1");
  bool any = false;
  while (fcl.step()) {
    any = true;
    html << "<tr><td>" << html_escape(fcl.get_text(0)) << "</td><td>" << fcl.get_int(1) << "</td></tr>\n";
  }
  if (!any) html << "<tr><td>none</td><td>0</td></tr>\n";
  db::Statement t = db.prepare(
      "SELECT coalesce(sum(r.wall_seconds), 0), coalesce(sum(r.steps), 0) FROM results r JOIN (" + scope.jobs_in_scope_sql() +
      ") cj ON cj.job_key = r.job_key");
  t.step();
  html << "</table>\n<p>Engine time: " << format_value(std::round(t.get_double(0)), 6) << " s over " << t.get_int(1)
       << " time steps.</p>\n";
  const std::vector<ModelSpeed> speed = campaign_speed(db, scope);
  if (!speed.empty()) {
    html << "<table><tr><th>model</th><th>jobs</th><th>t0 of flow per CPU-minute of a job: median</th><th>range</th></tr>\n";
    for (const ModelSpeed& m : speed)
      html << "<tr><td>" << html_escape(m.model) << "</td><td>" << m.jobs << "</td><td>" << format_value(m.median, 3)
           << "</td><td>" << format_value(m.min, 3) << " - " << format_value(m.max, 3) << "</td></tr>\n";
    html << "</table>\n";
  }
}

void fit_tables(std::ostringstream& html, const CampaignFits& fits) {
  html << "<h2>Beverloo fits Q = C (w - k)<sup>beta</sup></h2>\n"
       << "<p>Weighted least squares over the flowing points of each series (GSL, weights 1/Q_err<sup>2</sup>); errors "
          "from the covariance, not scaled by chi2_red (shown beside). A fit is flagged <em>not determined</em> when beta's relative error "
          "exceeds " << format_value(100 * kBetaDeterminedRelErr, 2) << " % or k lies outside [0, the smallest w].</p>\n"
       << "<table><tr><th>series</th><th>points</th><th>clogged</th><th>C / Q_0</th><th>k / sigma_avg</th><th>beta</th>"
       << "<th>chi2_red</th><th>quality</th></tr>\n";
  for (const Series& s : fits.series) {
    int flowing = 0;
    for (const auto& p : s.points) flowing += p.flowing();
    html << "<tr><td>" << html_escape(s.label) << "</td><td>" << flowing << "</td><td>" << s.clogged_points() << "</td>";
    if (s.fit) {
      const std::string quality = fit_quality(s);
      html << "<td>" << pm(s.fit->C, s.fit->C_err) << "</td><td>" << pm(s.fit->k, s.fit->k_err) << "</td><td>"
           << pm(s.fit->beta, s.fit->beta_err) << "</td><td>" << format_value(s.fit->chi2_red, 2) << "</td><td"
           << (quality == "ok" ? ">" : " class=flag>") << html_escape(quality) << "</td>";
    } else {
      html << "<td colspan=5>no fit: " << html_escape(s.message) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n<p><a href=\"beverloo_fits.csv\">CSV</a> &middot; <a href=\"beverloo_fits.md\">Markdown</a> "
          "(full precision)</p>\n";
  html << "<h2>Crossover fits beta(lambda)</h2>\n";
  if (fits.crossovers.empty()) {
    html << "<p>Not made: needs Beverloo fits at several finite lambda = zeta/mu with the other parameters equal "
            "(a sweep in lambda).</p>\n";
    return;
  }
  html << "<p>beta(lambda) = d - 1 - tanh[log10(lambda/lambda_c)/b]/2 with the paper's plateaus d - 1/2 and d - 3/2, "
          "and the same law with its plateaus free (beta(0) and beta(inf) fitted), beside the limits' own fits; and, "
          "without a sigmoid, where the measured exponents cross d - 1 (interpolated in log10 lambda; its sigma in "
          "decades: the exponents' errors or the replicas' spread, the interpolation's in quadrature).</p>\n"
       << "<table><tr><th>group</th><th>points</th><th>lambda_c</th><th>b</th><th>chi2_red</th>"
       << "<th>lambda_c, plateaus free</th><th>b</th><th>beta(0), beta(inf) fitted</th><th>chi2_red</th>"
       << "<th>beta = d - 1 at</th><th>beta(lambda=0)</th><th>beta(lambda=inf)</th></tr>\n";
  // lambda_c's run-to-run spread (in decades) where replicas give one
  auto spread = [](const Crossover::ReplicaSpread& r) {
    const std::string phrase = lambda_c_spread_phrase(r);
    return phrase.empty() ? phrase : "<br><small>" + phrase + "</small>";
  };
  for (const Crossover& g : fits.crossovers) {
    html << "<tr><td>" << html_escape(g.label) << "</td><td>" << g.fitted_points();
    if (!g.no_beverloo_law.empty())  // (their lambdas are in the fit's message when it fails for want of them)
      html << "<br><small>+" << g.no_beverloo_law.size() << " left out: " << no_beverloo_law_rule() << "</small>";
    html << "</td>";
    if (g.fit)
      html << "<td>" << pm(g.fit->lambda_c, g.fit->lambda_c_err) << spread(g.spread) << "</td><td>" << pm(g.fit->b, g.fit->b_err) << "</td><td>"
           << format_value(g.fit->chi2_red, 2) << "</td>";
    else
      html << "<td colspan=3>no fit: " << html_escape(g.message) << "</td>";
    if (g.fit_free)
      html << "<td>" << pm(g.fit_free->lambda_c, g.fit_free->lambda_c_err) << spread(g.spread_free) << "</td><td>" << pm(g.fit_free->b, g.fit_free->b_err)
           << "</td><td>" << pm(g.fit_free->beta_0, g.fit_free->beta_0_err) << ", "
           << pm(g.fit_free->beta_inf, g.fit_free->beta_inf_err) << "</td><td>" << format_value(g.fit_free->chi2_red, 2) << "</td>";
    else
      html << "<td colspan=4>no fit: " << html_escape(g.message_free) << "</td>";
    html << "<td>";
    if (const std::optional<MidpointCrossing> m = crossing_of_d_minus_1(g))
      html << format_value(std::pow(10.0, m->log10_lambda), 3) << "<br><small>" << format_value(m->lambda_lo, 2) << " .. "
           << format_value(m->lambda_hi, 2) << "; &plusmn; " << format_value(m->verdict_sigma(), 2) << " in log10</small>";
    html << "</td>";
    auto limit = [](const Series* s) { return s && s->fit ? pm(s->fit->beta, s->fit->beta_err) : std::string(); };
    html << "<td>" << limit(g.limit0) << "</td><td>" << limit(g.limit_inf) << "</td></tr>\n";
  }
  html << "</table>\n<p><a href=\"crossover_fits.csv\">CSV</a> &middot; <a href=\"crossover_fits.md\">Markdown</a> "
          "(full precision; both ways: <a href=\"crossover_fits_both_ways.csv\">CSV</a>)</p>\n";
}

/// The exponents fitted as the paper's authors fitted theirs, beside beverloo's, and the spread
/// over replicas (docs/paper.md): never instead of the fits above.
void both_ways_table(std::ostringstream& html, const CampaignFits& fits) {
  bool any = false;
  for (const Series& s : fits.series) any = any || !s.rate_is_c0();  // a series without a fit says why
  if (!any) return;
  html << "<h2>Every exponent two ways</h2>\n<p>beverloo's free fit (above) beside the fit the paper's authors made: "
          "unweighted, beta bounded to [0.4, 1.58], k to [0.5, 5], over 2 &lt; w &lt; 19 (a parameter on a bound is "
          "named), and with beta held at d - 3/2 and d - 1/2 as their Fig. 2 fits; and the spread of beta (and of the "
          "held fits' k) over the replicas, each fitted alone. The paper's published beta(lambda) is the bounded fit rescaled so that its three "
          "lowest-lambda points average 1.5; this report never rescales.</p>\n"
       << "<table><tr><th>series</th><th>beta (free)</th><th>spread over replicas</th><th>beta (authors' way)</th>"
       << "<th>on a bound</th><th>k at beta = d - 3/2</th><th>k at beta = d - 1/2</th></tr>\n";
  for (const Series& s : fits.series) {
    if (s.rate_is_c0()) continue;
    html << "<tr><td>" << html_escape(s.label) << "</td><td>" << (s.fit ? pm(s.fit->beta, s.fit->beta_err) : "") << "</td><td>"
         << (std::isnan(s.beta_replica_spread) ? std::string("-")
                                               : format_value(s.beta_replica_spread, 2) + " (" + std::to_string(s.replica_fits) + ")")
         << "</td>";
    if (s.authors_fit)
      html << "<td>" << pm(s.authors_fit->fit.beta, s.authors_fit->fit.beta_err) << "</td><td>"
           << html_escape(bound_names(*s.authors_fit)) << "</td>";
    else
      html << "<td colspan=2>" << html_escape(s.authors_message) << "</td>";
    for (const auto& [fixed, spread] : {std::pair{&s.authors_fixed_lo, s.k_at_beta_lo_replica_spread},
                                        std::pair{&s.authors_fixed_hi, s.k_at_beta_hi_replica_spread}}) {
      if (!*fixed) {
        html << "<td>-</td>";
        continue;
      }
      const std::string folded = folded_widths_note(**fixed);
      html << "<td>" << pm((*fixed)->k, (*fixed)->k_err) << (std::isnan(spread) ? "" : ", spread " + format_value(spread, 2))
           << (folded.empty() ? "" : "; " + html_escape(folded)) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n<p><a href=\"beverloo_fits_both_ways.csv\">CSV</a> &middot; "
          "<a href=\"beverloo_fits_both_ways.md\">Markdown</a></p>\n";
}

/// The paper's claims this campaign's fits can test (reports/paper_claims.h), with a verdict each.
void claims_table(std::ostringstream& html, const CampaignFits& fits) {
  const std::vector<ClaimCheck> checks = check_paper_claims(fits);
  if (checks.empty()) return;
  html << "<h2>The paper's claims this campaign tests</h2>\n<p>Each claim of the paper that these fits can check, "
          "with the paper's value and beverloo's (docs/paper.md has every claim, with the campaigns that measured "
          "them). The paper's values carry no errors, so the verdict uses the measurement's: it agrees when the "
          "difference is at most "
       << format_value(kClaimAgreeSigmas, 2)
       << " sigma, sigma the larger of the fit's error and the spread over replicas (z is the difference in "
          "sigma). A fit that is not determined is not judged. Nothing is rescaled.</p>\n"
       << "<table><tr><th>claim</th><th>checked on</th><th>paper</th><th>beverloo</th><th>verdict</th></tr>\n";
  for (const ClaimCheck& c : checks)
    html << "<tr><td>" << html_escape(c.claim) << "</td><td style=\"text-align:left\">" << html_escape(c.subject)
         << "</td><td>" << html_escape(c.paper) << "</td><td>" << html_escape(c.measured_text) << "</td><td"
         << (c.judged && !c.agrees ? " class=flag" : "") << ">" << html_escape(c.verdict) << "</td></tr>\n";
  html << "</table>\n<p><a href=\"paper_claims.csv\">CSV</a> &middot; <a href=\"paper_claims.md\">Markdown</a></p>\n";
}

/// Clogging as a result, per w of each series in which some run clogged (Kaplan-Meier).
void clog_table(std::ostringstream& html, const CampaignFits& fits) {
  bool any = false;
  for (const Series& s : fits.series) any = any || !s.clog_points.empty();
  if (!any) return;
  html << "<h2>Clogging</h2>\n<p>Per w, the time to a clog over the replicas by the Kaplan-Meier estimator (runs that "
          "ended flowing are censored at their end): the probability to clog within t_max with Greenwood's error, and "
          "the median time to a clog. Clogged points stay out of the Beverloo fits.</p>\n"
       << "<table><tr><th>series</th><th>w</th><th>runs</th><th>clogs</th><th>P(clog within t_max)</th>"
       << "<th>median time to a clog / t0</th></tr>\n";
  for (const Series& s : fits.series)
    for (const Series::ClogPoint& c : s.clog_points) {
      const double horizon = c.t_max > 0 ? c.t_max : INFINITY, median = c.km.median();
      html << "<tr><td>" << html_escape(s.label) << "</td><td>" << format_value(c.w, 4) << "</td><td>" << c.km.runs
           << "</td><td>" << c.km.clogs << "</td><td>" << pm(1 - c.km.at(horizon), c.km.err_at(horizon)) << "</td><td>"
           << (std::isnan(median) ? std::string("beyond the runs") : format_value(median, 3)) << "</td></tr>\n";
    }
  html << "</table>\n<p><a href=\"clog_statistics.csv\">CSV</a></p>\n";
}

/// An adaptive campaign's decisions (reports/adaptive_planner.h), in the order they were taken.
void adaptive_table(std::ostringstream& html, db::Database& db, const CampaignFits& fits, const CampaignScope& scope) {
  db::Statement has = db.prepare("SELECT count(*) FROM sqlite_master WHERE name = 'adaptive_decisions'");
  if (!has.step() || has.get_int(0) == 0) return;
  db::Statement st = db.prepare(
      "SELECT series_key, seq, action, w, replica, reason FROM adaptive_decisions "
      "WHERE " + scope.condition_on("campaign_id") + " ORDER BY rowid");
  bool any = false;
  while (st.step()) {
    if (!any)
      html << "<h2>Adaptive decisions</h2>\n<p>The planner's decisions (docs/sweeps.md, 'adaptive'): per series, one job "
              "at a time at the width that reduces the variance of k and beta most per CPU, until the targets are met, "
              "the budget is spent or no fit is possible.</p>\n"
           << "<table><tr><th>series</th><th>#</th><th>decision</th><th>w</th><th>replica</th><th>why</th></tr>\n";
    any = true;
    std::string label = st.get_text(0).substr(0, 12);
    for (const Series& s : fits.series)
      if (s.key == st.get_text(0)) label = s.label;
    html << "<tr><td>" << html_escape(label) << "</td><td>" << st.get_int(1) << "</td><td>" << html_escape(st.get_text(2))
         << "</td><td>" << (st.is_null(3) ? std::string() : table_number(st.get_double(3), 4)) << "</td><td>"
         << (st.is_null(4) ? std::string() : std::to_string(st.get_int(4))) << "</td><td style=\"text-align:left\">"
         << html_escape(st.get_text(5)) << "</td></tr>\n";
  }
  if (any) html << "</table>\n";
}

}  // namespace

std::string index_html(db::Database& db, const CampaignFits& fits, const std::vector<ReportFigure>& figures,
                       const CampaignScope& scope) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<link rel=\"icon\" href=\"data:,\">\n<title>beverloo report</title>\n"
       << "<style>body{font-family:sans-serif;max-width:1100px;margin:auto;padding:0 8px}"
       << "table{border-collapse:collapse;display:block;overflow-x:auto}"
       << "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}td:first-child{text-align:left}"
       << "td.flag{color:#a00}img{max-width:100%;height:auto}</style></head><body>\n";
  run_summary(html, db, scope);
  fit_tables(html, fits);
  both_ways_table(html, fits);
  claims_table(html, fits);
  clog_table(html, fits);
  adaptive_table(html, db, fits, scope);
  html << "<h2>Figures</h2>\n";
  for (const ReportFigure& f : figures) {
    html << "<h3>" << html_escape(f.title) << "</h3>\n";
    if (f.made)
      html << "<p><img src=\"" << f.name << ".svg\" alt=\"" << html_escape(f.title) << "\"></p>\n<p><a href=\"" << f.name
           << ".png\">PNG</a> &middot; <a href=\"" << f.name << ".dat\">data</a> &middot; <a href=\"" << f.name
           << ".gp\">gnuplot script</a></p>\n";
    else
      html << "<p>Not made: " << html_escape(f.why_not) << ".</p>\n";
  }
  html << "</body></html>\n";
  return html.str();
}

}  // namespace beverloo
