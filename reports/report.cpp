#include "report.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "reports/campaign_fits.h"

namespace beverloo {
namespace fs = std::filesystem;
namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}

/// A figure: data blocks (gnuplot "index"), a plot script body; rendered to SVG and PNG.
struct Figure {
  Figure(std::string n, std::string t, std::string x, std::string y, std::string e = "")
      : name(std::move(n)), title(std::move(t)), xlabel(std::move(x)), ylabel(std::move(y)), extra(std::move(e)) {}
  std::string name, title, xlabel, ylabel, extra;  ///< extra: more "set" lines (log scales, ...)
  std::ostringstream data;
  std::vector<std::string> plots;  ///< plot clauses; "DATA" stands for the data file
  std::string body;                ///< instead of plots: whole gnuplot commands (multiplot), "DATA" as above
  int blocks = 0;
  void begin_block(const std::string& header) {
    if (blocks++) data << "\n\n";
    data << "# " << header << "\n";
  }
};

void render(Figure& f, const fs::path& dir) {
  const std::string dat = f.name + ".dat";
  write_text_atomically((dir / dat).string(), f.data.str());
  std::ostringstream gp;
  gp << "# " << f.title << "\n# Rendered by beverloo report; edit and run `gnuplot " << f.name << ".gp` in this directory.\n"
     << "set title \"" << f.title << "\" noenhanced font ',11'\nset xlabel \"" << f.xlabel << "\" noenhanced\n"
     << "set ylabel \"" << f.ylabel << "\" noenhanced\nset key inside top left font ',9' noenhanced\nset grid\n" << f.extra;
  auto with_data = [&](std::string text) {
    for (std::size_t pos; (pos = text.find("DATA")) != std::string::npos;) text.replace(pos, 4, "'" + dat + "'");
    return text;
  };
  std::string plot = f.body.empty() ? "plot " : with_data(f.body);
  for (std::size_t k = 0; f.body.empty() && k < f.plots.size(); ++k) plot += (k ? ", \\\n     " : "") + with_data(f.plots[k]);
  // the commands once per terminal (replot cannot repeat a multiplot)
  gp << "set terminal svg size 900,600 dynamic background rgb 'white'\nset output '" << f.name << ".svg'\n" << plot
     << "\nset terminal pngcairo size 900,600\nset output '" << f.name << ".png'\n" << plot << "\nunset output\n";
  write_text_atomically((dir / (f.name + ".gp")).string(), gp.str());
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + f.name + ".gp' 2> '" + f.name + ".log'";
  const int rc = std::system(cmd.c_str());
  if (rc != 0 || !fs::exists(dir / (f.name + ".svg")) || !fs::exists(dir / (f.name + ".png")))
    throw IoError("gnuplot failed on " + (dir / (f.name + ".gp")).string() + " (see " + f.name + ".log)");
  fs::remove(dir / (f.name + ".log"));
}

/// Renders the figure if it has data; otherwise records what data it needs.
ReportFigure finish(Figure& f, int blocks, const fs::path& dir, const std::string& needs) {
  ReportFigure r{f.name, f.title, false, ""};
  if (blocks == 0) {
    r.why_not = needs;
  } else {
    render(f, dir);
    r.made = true;
  }
  return r;
}

}  // namespace

std::vector<ReportFigure> write_report(const std::string& campaign_dir, const std::string& out_dir) {
  // the fits are written into the database: one writer
  CampaignWriter writer(campaign_dir, CampaignWriter::Open::MustExist);
  db::Database& db = writer.db();
  const fs::path dir(out_dir);
  fs::create_directories(dir);
  const CampaignFits fits = fit_campaign(db);
  store_fits(db, fits);
  write_fit_tables(fits, out_dir);
  std::vector<ReportFigure> made;

  // 1. Q versus w with the fitted curves
  {
    Figure f("Q_vs_w",
             "Flow rate Q versus orifice width w, with fits Q = C (w - k)^beta",
             "w / sigma_avg", "Q / Q_0");
    int block = 0;
    for (const Series& s : fits.series) {
      f.begin_block(s.label + ": w Q Q_err (flowing points)");
      for (const auto& p : s.points)
        if (p.flowing()) f.data << num(p.w) << " " << num(p.Q) << " " << num(p.Q_err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2:3 with yerrorbars pt 7 lc " +
                        std::to_string(block + 1) + " title \"" + s.label + "\"");
      ++block;
      if (s.fit) {
        f.begin_block(s.label + ": fitted curve w Q");
        const double lo = std::max(s.fit->k + 1e-3, s.points.front().w - 0.5), hi = s.points.back().w + 0.5;
        for (int i = 0; i <= 100; ++i) {
          const double w = lo + (hi - lo) * i / 100;
          f.data << num(w) << " " << num(beverloo_model(w, s.fit->C, s.fit->k, s.fit->beta)) << "\n";
        }
        f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2 with lines lc " + std::to_string(block) +
                          " notitle");
        ++block;
      }
    }
    made.push_back(finish(f, block, dir, "no finished jobs"));
  }
  // 2. collapse: log10(Q/C) versus log10(w - k), with reference slopes
  {
    Figure f("loglog_collapse",
             "log10(Q/C) versus log10(w - k), reference slopes 1/2, 3/2, 5/2",
             "log10(w/sigma_avg - k)", "log10(Q/C)");
    int block = 0;
    for (const Series& s : fits.series) {
      if (!s.fit) continue;
      f.begin_block(s.label + ": log10(w - k) log10(Q/C)");
      for (const auto& p : s.points)
        if (p.flowing()) f.data << num(std::log10(p.w - s.fit->k)) << " " << num(std::log10(p.Q / s.fit->C)) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block++) + " using 1:2 with points pt 7 title \"" + s.label +
                        " (beta " + num(std::round(s.fit->beta * 100) / 100) + ")\"");
    }
    f.plots.push_back("0.5*x with lines dt 2 lc rgb 'gray40' title 'slope 1/2'");
    f.plots.push_back("1.5*x with lines dt 3 lc rgb 'gray40' title 'slope 3/2'");
    f.plots.push_back("2.5*x with lines dt 4 lc rgb 'gray40' title 'slope 5/2'");
    made.push_back(finish(f, block, dir, "no series could be fitted (at least 4 flowing w per series)"));
  }
  // 3. beta versus lambda with the sigmoid
  {
    Figure f("beta_vs_lambda",
             "Exponent beta versus lambda = zeta/mu, with beta = d - 1 - tanh[log10(lambda/lambda_c)/b]/2",
             "lambda", "beta", "set logscale x\nset format x '10^{%L}'\n");
    int block = 0;
    for (const Crossover& g : fits.crossovers) {
      if (g.finite.empty()) continue;
      f.begin_block(g.label + ": lambda beta beta_err");
      for (const Series* s : g.finite) f.data << num(s->lambda) << " " << num(s->fit->beta) << " " << num(s->fit->beta_err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block++) + " using 1:2:3 with yerrorbars pt 7 title \"" + g.label + "\"");
      if (g.fit) {
        f.begin_block(g.label + ": sigmoid lambda beta");
        const double lo = std::log10(g.finite.front()->lambda) - 1, hi = std::log10(g.finite.back()->lambda) + 1;
        for (int i = 0; i <= 100; ++i) {
          const double l = std::pow(10.0, lo + (hi - lo) * i / 100);
          f.data << num(l) << " " << num(crossover_model(g.dimension, l, g.fit->lambda_c, g.fit->b)) << "\n";
        }
        f.plots.push_back("DATA index " + std::to_string(block++) + " using 1:2 with lines title \"lambda_c = " +
                          num(std::round(g.fit->lambda_c * 1e4) / 1e4) + "\"");
      }
      for (const auto& [lim, name] : {std::pair{g.limit0, "lambda = 0"}, std::pair{g.limit_inf, "lambda = inf"}})
        if (lim && lim->fit)
          f.plots.push_back(num(lim->fit->beta) + " with lines dt 2 title \"" + g.label + ", " + name + "\"");
    }
    made.push_back(finish(f, block, dir, "needs series at several finite lambda > 0 (a lambda sweep)"));
  }
  // 4. k versus stiffness, per dissipation setting: E_sp for SP, K_b for DP (the paper's softness
  // axes; DP groups also keep K_l and E_c fixed)
  for (const bool dp : {false, true}) {
    Figure f(dp ? "k_vs_Kb" : "k_vs_Esp", dp ? "Offset k versus bending stiffness K_b (DP)" : "Offset k versus stiffness E_sp (SP)",
             dp ? "K_b" : "E_sp", "k", "set logscale x\n");
    auto stiffness = [dp](const Series* s) { return dp ? s->K_b : s->E_sp; };
    std::map<std::string, std::vector<const Series*>> by;
    for (const Series& s : fits.series) {
      if (!s.fit || s.is_dp() != dp) continue;
      std::string label = std::to_string(s.dimension) + "D ";
      if (dp) label += s.model + " K_l=" + num(s.K_l) + " E_c=" + num(s.E_c) + " ";
      by[label + "lambda=" + format_lambda(s.lambda) + " N=" + std::to_string(s.N)].push_back(&s);
    }
    int block = 0;
    for (auto& [label, list] : by) {
      std::set<double> values;
      for (const Series* s : list) values.insert(stiffness(s));
      if (values.size() < 2) continue;
      std::sort(list.begin(), list.end(), [&](const Series* a, const Series* b) { return stiffness(a) < stiffness(b); });
      f.begin_block(label + (dp ? ": K_b k k_err" : ": E_sp k k_err"));
      for (const Series* s : list) f.data << num(stiffness(s)) << " " << num(s->fit->k) << " " << num(s->fit->k_err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block++) + " using 1:2:3 with yerrorlines pt 7 title \"" + label + "\"");
    }
    made.push_back(finish(f, block, dir,
                          dp ? "needs fitted DP series at two or more K_b with the other parameters equal"
                             : "needs fitted SP series at two or more E_sp with the other parameters equal"));
  }
  // 5. k heat map over (K_l, K_b), one panel per DP group (model, E_c, lambda, N, angles)
  {
    Figure f("k_heatmap_Kl_Kb", "Offset k over (K_l, K_b) (DP)", "K_l", "K_b");
    std::map<std::string, std::vector<const Series*>> by;
    for (const Series& s : fits.series)
      if (s.fit && s.is_dp())
        by[s.model + " E_c=" + num(s.E_c) + " lambda=" + format_lambda(s.lambda) + " N=" + std::to_string(s.N) +
           (s.theta_left != 90 || s.theta_right != 90 ? " theta=" + num(s.theta_left) + "/" + num(s.theta_right) : "")]
            .push_back(&s);
    std::vector<std::pair<std::string, std::vector<const Series*>>> panels;
    double k_lo = INFINITY, k_hi = -INFINITY;
    for (auto& [label, list] : by) {
      std::set<std::pair<double, double>> grid;
      for (const Series* s : list) grid.insert({s->K_l, s->K_b});
      if (grid.size() < 2 || panels.size() == 4) continue;  // at most four panels; all fits are in the tables
      for (const Series* s : list) k_lo = std::min(k_lo, s->fit->k), k_hi = std::max(k_hi, s->fit->k);
      panels.emplace_back(label, list);
    }
    std::ostringstream body;
    if (!panels.empty()) {
      body << "set logscale xy\nset offsets graph 0.15, graph 0.15, graph 0.15, graph 0.15\nset palette rgb 33,13,10\n"
           << "set cblabel 'k'\nset cbrange [" << num(k_lo) << ":" << num(k_hi > k_lo ? k_hi : k_lo + 1) << "]\n"
           << "set multiplot layout 1," << panels.size() << " title \"" << f.title << "\" noenhanced\n";
      int block = 0;
      for (const auto& [label, list] : panels) {
        f.begin_block(label + ": K_l K_b k k_err");
        for (const Series* s : list)
          f.data << num(s->K_l) << " " << num(s->K_b) << " " << num(s->fit->k) << " " << num(s->fit->k_err) << "\n";
        body << "set title \"" << label << "\" noenhanced font ',9'\n"
             << "plot DATA index " << block << " using 1:2:3 with points pt 5 ps 5 palette notitle, \\\n"
             << "     DATA index " << block << " using 1:2:(sprintf('%.2f', $3)) with labels offset 0,2 font ',8' notitle\n";
        ++block;
      }
      body << "unset multiplot";
      f.body = body.str();
    }
    made.push_back(finish(f, static_cast<int>(panels.size()), dir,
                          "needs fitted DP series at two or more (K_l, K_b) with the other parameters equal"));
  }
  // 6. velocity profiles for several w
  {
    Figure f("velocity_profiles",
             "Coarse-grained velocity along gravity v_g(h) on the centre line",
             "h / sigma_avg", "v_g");
    int block = 0;
    int shown = 0;
    for (const Series& s : fits.series) {
      if (shown++ >= 4) break;  // the first four series; the data for all are in the database
      db::Statement st = db.prepare(
          "SELECT j.w, p.h, p.v_g, p.v_g_err FROM velocity_profiles p JOIN jobs j ON j.key = p.job_key "
          "WHERE p.job_key = ?1 ORDER BY p.h");
      for (const std::string& key : s.job_keys) {
        st.bind(1, key);
        bool any = false;
        double w = 0;
        std::ostringstream rows;
        while (st.step()) {
          any = true;
          w = st.get_double(0);
          rows << num(st.get_double(1)) << " " << num(st.get_double(2)) << " " << num(st.get_double(3)) << "\n";
        }
        st.reset();
        if (!any) continue;
        f.begin_block(s.label + " w=" + num(w) + ": h v_g v_g_err");
        f.data << rows.str();
        f.plots.push_back("DATA index " + std::to_string(block++) + " using 1:2 with lines title \"" + s.label + ", w = " +
                          num(w) + "\"");
      }
    }
    made.push_back(finish(f, block, dir, "no velocity profiles in the database"));
  }

  // index.html
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>beverloo report</title>\n"
       << "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}table{border-collapse:collapse}"
       << "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}td:first-child{text-align:left}"
       << "img{max-width:100%}</style></head><body>\n";
  {
    db::Statement c = db.prepare("SELECT name, created_at FROM campaigns ORDER BY id DESC LIMIT 1");
    const bool have = c.step();
    html << "<h1>beverloo report: " << html_escape(have ? c.get_text(0) : std::string("(no campaign)")) << "</h1>\n";
    html << "<h2>Run summary</h2>\n<table><tr><th>jobs by state</th><th>count</th></tr>\n";
    db::Statement s = db.prepare(
        "SELECT j.state, count(*) FROM jobs j JOIN campaign_jobs cj ON cj.job_key = j.key "
        "WHERE cj.campaign_id = (SELECT max(id) FROM campaigns) GROUP BY j.state ORDER BY j.state");
    while (s.step()) html << "<tr><td>" << s.get_text(0) << "</td><td>" << s.get_int(1) << "</td></tr>\n";
    html << "</table>\n<table><tr><th>failed attempts by class</th><th>count</th></tr>\n";
    db::Statement fcl = db.prepare(
        "SELECT a.failure_class, count(*) FROM attempts a JOIN campaign_jobs cj ON cj.job_key = a.job_key "
        "WHERE cj.campaign_id = (SELECT max(id) FROM campaigns) AND a.failure_class IS NOT NULL GROUP BY 1");
    bool any = false;
    while (fcl.step()) {
      any = true;
      html << "<tr><td>" << fcl.get_text(0) << "</td><td>" << fcl.get_int(1) << "</td></tr>\n";
    }
    if (!any) html << "<tr><td>none</td><td>0</td></tr>\n";
    db::Statement t = db.prepare(
        "SELECT coalesce(sum(r.wall_seconds), 0), coalesce(sum(r.steps), 0) FROM results r JOIN campaign_jobs cj ON "
        "cj.job_key = r.job_key WHERE cj.campaign_id = (SELECT max(id) FROM campaigns)");
    t.step();
    html << "</table>\n<p>Engine time: " << num(std::round(t.get_double(0))) << " s over " << t.get_int(1)
         << " time steps.</p>\n";
  }
  html << "<h2>Beverloo fits Q = C (w - k)<sup>beta</sup></h2>\n<table><tr><th>series</th><th>points</th><th>clogged</th>"
       << "<th>C</th><th>k</th><th>beta</th><th>chi2_red</th></tr>\n";
  for (const Series& s : fits.series) {
    int flowing = 0;
    for (const auto& p : s.points) flowing += p.flowing();
    html << "<tr><td>" << html_escape(s.label) << "</td><td>" << flowing << "</td><td>" << s.clogged_points() << "</td>";
    if (s.fit)
      html << "<td>" << num(s.fit->C) << " &plusmn; " << num(s.fit->C_err) << "</td><td>" << num(s.fit->k) << " &plusmn; "
           << num(s.fit->k_err) << "</td><td>" << num(s.fit->beta) << " &plusmn; " << num(s.fit->beta_err) << "</td><td>"
           << num(s.fit->chi2_red) << "</td>";
    else
      html << "<td colspan=4>no fit: " << html_escape(s.message) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n<p><a href=\"beverloo_fits.csv\">CSV</a> &middot; <a href=\"beverloo_fits.md\">Markdown</a></p>\n";
  html << "<h2>Crossover fits beta(lambda)</h2>\n<table><tr><th>group</th><th>points</th><th>lambda_c</th><th>b</th>"
       << "<th>beta(lambda=0)</th><th>beta(lambda=inf)</th></tr>\n";
  for (const Crossover& g : fits.crossovers) {
    html << "<tr><td>" << html_escape(g.label) << "</td><td>" << g.finite.size() << "</td>";
    if (g.fit)
      html << "<td>" << num(g.fit->lambda_c) << " &plusmn; " << num(g.fit->lambda_c_err) << "</td><td>" << num(g.fit->b)
           << " &plusmn; " << num(g.fit->b_err) << "</td>";
    else
      html << "<td colspan=2>no fit: " << html_escape(g.message) << "</td>";
    html << "<td>" << (g.limit0 && g.limit0->fit ? num(g.limit0->fit->beta) : "") << "</td><td>"
         << (g.limit_inf && g.limit_inf->fit ? num(g.limit_inf->fit->beta) : "") << "</td></tr>\n";
  }
  html << "</table>\n<p><a href=\"crossover_fits.csv\">CSV</a> &middot; <a href=\"crossover_fits.md\">Markdown</a></p>\n";
  html << "<h2>Figures</h2>\n";
  for (const ReportFigure& f : made) {
    html << "<h3>" << html_escape(f.title) << "</h3>\n";
    if (f.made)
      html << "<p><img src=\"" << f.name << ".svg\" alt=\"" << html_escape(f.title) << "\"></p>\n<p><a href=\"" << f.name
           << ".png\">PNG</a> &middot; <a href=\"" << f.name << ".dat\">data</a> &middot; <a href=\"" << f.name
           << ".gp\">gnuplot script</a></p>\n";
    else
      html << "<p>Not made: " << html_escape(f.why_not) << ".</p>\n";
  }
  html << "</body></html>\n";
  write_text_atomically((dir / "index.html").string(), html.str());
  return made;
}

}  // namespace beverloo
