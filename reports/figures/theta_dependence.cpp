// The paper's Fig. 6 in its own form, beside the exponents of beta_vs_lambda (its panel a):
// (left) lambda_c against the hopper angle theta_w for the beta(lambda) groups that differ only
// in theta_w, both crossover fits (the paper's fixed plateaus, and free ones), with the paper's
// stated values in grey (5e-2 at 90 deg, 6e-3 at 20 deg, a plateau ~5e-3 for theta_w <= 30 deg);
// (right, its panel b) the ratio of the mean drag force to the mean friction force on a particle,
// |F_zeta| / |F_mu|, against theta_w at the paper's lambda = 1e-2: each series' mean over its
// runs (error: their standard error), interpolated in log-log between the two series of the group
// that bracket 1e-2, so that every angle is read at the same lambda; where angles are read at
// 1e-2 itself, also one dotted line per width; (a third panel, for groups without a crossover
// fit) beta at a lambda two or more angles share against theta_w, with the interval the paper's
// Eq. 2 puts it in at the angles where the paper states lambda_c (claims table: "Fig. 6a at one
// lambda"). Never rescaled.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/crossover_groups.h"
#include "reports/number_format.h"
#include "reports/series_fits.h"

namespace beverloo::figures {
namespace {

/// A family's name: what a theta_w series of beta(lambda) groups shares that a reader tells
/// families apart by (the model, its stiffness, d, N and the lambda axis: the text's zeta / mu
/// or the authors' drag rate). Two families can share it (E_w or the reinjection rule differ);
/// they are told apart by their key (see lambda_c_vs_theta).
std::string family_name(const Series& s) {
  return std::to_string(s.dimension) + "D " + s.stiffness + " N=" + std::to_string(s.N) +
         (s.drag_rate > 0 ? " (drag rate)" : "");
}

/// lambda as a key that the same lambda at two angles shares (six significant digits: the
/// series of one sweep differ in theta_w alone, the rounding only guards the last bits).
double lambda_key(double lambda) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", lambda);
  return std::strtod(buf, nullptr);
}

/// The frame of the lambda_c panel, in log10 lambda: every drawn value, and the bars of those
/// known to kFrameDecades or better. A wider bar is cut at the frame and counted: the text set's
/// Fig. 6 has a free-plateau lambda_c at 30 deg whose replicas spread it over 2.5 decades, and
/// its bar squeezed every other lambda_c into a third of the panel.
constexpr double kFrameDecades = 1.0, kFrameMarginDecades = 0.25;
struct LogFrame {
  double lo = INFINITY, hi = -INFINITY;
  int cut = 0;
  void add(double value, double log10_sigma) {
    if (!(value > 0)) return;
    const double x = std::log10(value), bar = std::isfinite(log10_sigma) && log10_sigma <= kFrameDecades ? log10_sigma : 0;
    lo = std::min(lo, x - bar), hi = std::max(hi, x + bar);
    cut += std::isfinite(log10_sigma) && log10_sigma > kFrameDecades;
  }
};

}  // namespace

ReportFigure lambda_c_vs_theta(const FigureContext& c) {
  Figure f("lambda_c_vs_theta",
           "Crossover lambda_c and the drag-to-friction force ratio versus the hopper angle theta_w (the paper's Fig. 6)",
           "theta_w (deg)", "lambda_c");
  // Families: the groups that differ only in theta_w (Crossover::angle_family), so that one
  // angle holds exactly one group of a family. Each panel takes a family at two or more angles:
  // the left one where a group has a crossover fit, the right one where a group has a force
  // ratio near lambda = 1e-2, fitted or not (one width per angle measures a ratio; beta needs
  // several).
  struct Family {
    std::string name;
    std::map<double, const Crossover*> fitted;          // theta_w -> its group with a crossover fit
    std::map<double, ForceRatioAtLambda> ratio;         // theta_w -> its group's force ratio
    // lambda -> theta_w -> the series at that lambda, at the lambdas where some group has no
    // crossover fit (its beta there is all it has); a fitted group's series at such a lambda is
    // drawn beside it
    std::map<double, std::map<double, const Series*>> one_lambda;
    bool any_one_lambda() const {
      return std::any_of(one_lambda.begin(), one_lambda.end(), [](const auto& l) { return l.second.size() >= 2; });
    }
    bool shown() const { return fitted.size() >= 2 || ratio.size() >= 2 || any_one_lambda(); }
  };
  std::map<std::string, Family> by_key;
  for (const auto& [key, by_theta] : angle_families(c.fits.crossovers, /*fitted_only=*/false)) {
    Family family;
    for (const auto& [theta, g] : by_theta) {
      if (g->fit || g->fit_free) family.fitted.emplace(theta, g);
      if (const auto r = force_ratio_at_paper_lambda(*g)) family.ratio.emplace(theta, *r);
      if (!g->fit && !g->fit_free)
        for (const Series* s : g->finite) family.one_lambda[lambda_key(s->lambda)].emplace(theta, s);
    }
    for (const auto& [theta, g] : by_theta)
      if (g->fit || g->fit_free)
        for (const Series* s : g->finite)
          if (const auto at = family.one_lambda.find(lambda_key(s->lambda)); at != family.one_lambda.end())
            at->second.emplace(theta, s);
    if (!family.shown()) continue;
    const Crossover& any = *by_theta.begin()->second;
    family.name = family_name(!any.finite.empty() ? *any.finite.front() : *any.unfitted.front());
    by_key.emplace(key, std::move(family));
  }
  // by name (a stable order for the figure), a name shared by families made unique by their key
  std::map<std::string, int> name_uses;
  for (const auto& [key, family] : by_key) ++name_uses[family.name];
  std::map<std::string, const Family*> families;
  for (const auto& [key, family] : by_key)
    families.emplace(name_uses[family.name] > 1 ? family.name + " [" + key.substr(0, 8) + "]" : family.name, &family);
  if (!families.empty()) {
    std::ostringstream left, left_plots, right, right_plots, third, third_plots;
    left << "set title 'lambda_c (midpoint of beta(lambda))' noenhanced font ',9'\nset logscale y\n"
         << "set format y '10^{%L}'\nset xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel 'lambda_c'\n";
    right << "set title 'Fig. 6b: force ratio at lambda = 1e-2' noenhanced font ',9'\nunset logscale y\nset format y '%g'\n"
          << "set xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel '|F_zeta| / |F_mu|' noenhanced\n";
    // the paper's values: 5e-2 at 90 deg, ~6e-3 at 20 deg, a plateau ~5e-3 below 30 deg
    const int paper = f.begin_block("the paper: theta_w lambda_c");
    f.data << "90 0.05\n20 0.006\n";
    LogFrame frame;
    for (const double value : {0.05, 0.006, 0.005}) frame.add(value, 0);
    const int plateau = f.begin_block("the paper's plateau: theta_w lambda_c");
    f.data << "0 0.005\n30 0.005\n";
    third << "set title 'Fig. 6a at one lambda: beta (grey: the paper)' noenhanced font ',9'\n"
          << "unset logscale y\nset format y '%g'\nset xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel 'beta'\n";
    std::map<std::pair<int, double>, int> paper_intervals;  // (d, lambda) -> its block
    // one family: its name heads the figure and each legend entry says only what it draws (a DP
    // family's name is too long for a panel's legend)
    auto legend = [&](const std::string& name, const std::string& what) {
      return gnuplot_string(families.size() == 1 ? what : name + ", " + what);
    };
    int k = 0;
    for (const auto& [name, family] : families) {
      const std::string style = series_style(k++, static_cast<int>(families.size()));
      if (family->fitted.size() >= 2) {
        // the bars: lambda_c times and over 10^sigma, sigma the larger of the fit's error of
        // log10 lambda_c and its spread over the replicas' own fits (as the claims table judges it)
        auto row = [&](double theta, const CrossoverFit& fit, const Crossover::ReplicaSpread& spread) {
          const double sigma = log10_lambda_c_sigma(fit, spread);
          frame.add(fit.lambda_c, sigma);
          f.data << num(theta) << " " << num(fit.lambda_c) << " " << num(fit.lambda_c_err) << " "
                 << num(spread.log10_lambda_c) << " " << num(fit.lambda_c * std::pow(10.0, -sigma)) << " "
                 << num(fit.lambda_c * std::pow(10.0, sigma)) << "\n";
        };
        const std::string columns = ": theta_w lambda_c lambda_c_err log10_lambda_c_replica_spread bar_low bar_high";
        const int fixed = f.begin_block(name + columns + " (the paper's fixed plateaus)");
        for (const auto& [theta, g] : family->fitted)
          if (g->fit) row(theta, *g->fit, g->spread);
        const int free_block = f.begin_block(name + columns + " (plateaus free)");
        for (const auto& [theta, g] : family->fitted)
          if (g->fit_free) row(theta, *g->fit_free, g->spread_free);
        left_plots << ", \\\n     DATA index " << fixed << " using 1:2:5:6 with yerrorlines " << style << " title "
                   << legend(name, "plateaus 3/2, 1/2") << ", \\\n     DATA index " << free_block
                   << " using 1:2:5:6 with yerrorlines dt 2 " << style.substr(0, style.find(" pt")) << " pt 4 title "
                   << legend(name, "plateaus free");
        // without a sigmoid: where the measured beta crosses d - 1 (bars: the larger of the
        // exponents' error and the replicas' spread with the interpolation's in quadrature, as
        // the claims table judges it)
        std::vector<std::pair<double, MidpointCrossing>> crossings;
        for (const auto& [theta, g] : family->fitted)
          if (const auto m = crossing_of_d_minus_1(*g)) crossings.emplace_back(theta, *m);
        if (crossings.size() >= 2) {
          const int crossing_block =
              f.begin_block(name + ": theta_w lambda_at_beta_d_minus_1 log10_sigma log10_replica_spread bar_low bar_high "
                                   "log10_interpolation_error");
          for (const auto& [theta, m] : crossings) {
            const double sigma = m.verdict_sigma();
            frame.add(std::pow(10.0, m.log10_lambda), sigma);
            f.data << num(theta) << " " << num(std::pow(10.0, m.log10_lambda)) << " " << num(m.sigma) << " " << num(m.spread)
                   << " " << num(std::pow(10.0, m.log10_lambda - sigma)) << " " << num(std::pow(10.0, m.log10_lambda + sigma))
                   << " " << num(m.interpolation) << "\n";
          }
          left_plots << ", \\\n     DATA index " << crossing_block << " using 1:2:5:6 with yerrorlines dt 3 "
                     << style.substr(0, style.find(" pt")) << " pt 8 title " << legend(name, "where beta crosses d - 1");
        }
      }
      if (family->ratio.size() >= 2) {
        // force_ratio_err NaN: a series of one run from an engine before the run's own error
        // (force_ratio_err of result.h5); drawn without a bar
        const int ratio =
            f.begin_block(name + ": theta_w force_ratio force_ratio_err lambda runs lambda_below lambda_above");
        for (const auto& [theta, r] : family->ratio)
          f.data << num(theta) << " " << num(r.mean) << " " << num(r.err) << " " << num(r.lambda) << " " << r.runs
                 << " " << num(r.lambda_below) << " " << num(r.lambda_above) << "\n";
        right_plots << (right_plots.tellp() > 0 ? ", \\\n     " : "plot ") << "DATA index " << ratio
                    << " using 1:2:($3 == $3 ? $3 : 0) with yerrorlines " << style << " title " << legend(name, "mean over the runs");
        // and width by width, thin and dotted in the family's colour, where two or more angles are
        // read at lambda = 1e-2 itself at that width: the ratio grows with w, so the mean's bar
        // holds that growth; a width's own line shows the rise the claims table judges (paired)
        std::map<double, std::map<double, double>> by_width;  // w -> theta_w -> its runs' mean ratio
        for (const auto& [theta, r] : family->ratio)
          if (r.series)
            for (const auto& [w, value] : r.series->force_ratio.by_w) by_width[w][theta] = value;
        bool titled = false;
        for (const auto& [w, at] : by_width) {
          if (at.size() < 2) continue;
          const int line = f.begin_block(name + ", w = " + num(w) + ": theta_w force_ratio (mean of the width's runs)");
          for (const auto& [theta, value] : at) f.data << num(theta) << " " << num(value) << "\n";
          right_plots << ", \\\n     DATA index " << line << " using 1:2 with linespoints dt 3 lw 0.7 ps 0.4 "
                      << style.substr(0, style.find(" pt")) << " pt 1 "
                      << (titled ? std::string("notitle") : "title " + legend(name, "one line per width"));
          titled = true;
        }
      }
      for (const auto& [lambda, at] : family->one_lambda) {
        if (at.size() < 2) continue;
        const int d = at.begin()->second->dimension;
        if (!paper_intervals.count({d, lambda})) {
          const int block = f.begin_block("the paper's Eq. 2 at lambda = " + num(lambda) +
                                          " (d = " + std::to_string(d) + "): theta_w beta_mid beta_low beta_high lambda_c");
          for (const double theta : {20.0, 30.0, 90.0})
            if (const auto lc = paper_lambda_c_at_angle(d, theta)) {
              const auto [low, high] = paper_beta_interval(d, lambda, *lc);
              f.data << num(theta) << " " << num(d - 1) << " " << num(low) << " " << num(high) << " " << num(*lc) << "\n";
            }
          paper_intervals[{d, lambda}] = block;
          third_plots << (third_plots.tellp() > 0 ? ", \\\n     " : "plot ") << "DATA index " << block
                      << " using 1:2:3:4 with yerrorbars pt 0 lw 3 lc rgb 'gray60' title "
                      << gnuplot_string("paper, lambda = " + num(lambda));
        }
        const int block = f.begin_block(name + ", lambda = " + num(lambda) + ": theta_w beta beta_err beta_replica_spread");
        for (const auto& [theta, s] : at)
          f.data << num(theta) << " " << num(s->fit->beta) << " " << num(s->fit->beta_err) << " "
                 << num(s->beta_replica_spread) << "\n";
        third_plots << (third_plots.tellp() > 0 ? ", \\\n     " : "plot ") << "DATA index " << block
                    << " using 1:2:3 with yerrorlines " << style << " title "
                    << legend(name, "lambda = " + num(lambda));
      }
    }
    // a frame only where a bar is cut (otherwise gnuplot's own range holds every bar), undone
    // after the panel so that the next panels scale themselves
    std::string undo_frame;
    if (frame.cut > 0) {
      left << "set yrange [" << num(std::pow(10.0, frame.lo - kFrameMarginDecades)) << ":"
           << num(std::pow(10.0, frame.hi + kFrameMarginDecades)) << "]\nset label 1 "
           << gnuplot_string(std::to_string(frame.cut) + (frame.cut == 1 ? " bar" : " bars") + " wider than " +
                             format_value(kFrameDecades, 2) + " decade cut at the frame (the .dat has them)")
           << " at graph 0.02, graph 0.04 font ',8' noenhanced\n";
      undo_frame = "\nunset label 1\nset autoscale y";
    }
    left << "plot DATA index " << paper << " using 1:2 with points pt 6 ps 2 lc rgb 'gray50' title 'paper: 5e-2 (90), 6e-3 (20)', \\\n"
         << "     DATA index " << plateau << " using 1:2 with lines " << kPaperLineStyle << " title 'paper: plateau ~5e-3'"
         << left_plots.str() << undo_frame;
    std::ostringstream body;
    // panel a where a family has lambda_c at two angles, b where it has force ratios (or, beside
    // a, a line that says why not), c where it has beta at one lambda at two angles
    std::vector<std::string> panels;
    const bool lambda_c_panel = left_plots.tellp() > 0, one_lambda_panel = third_plots.tellp() > 0;
    if (lambda_c_panel) panels.push_back(left.str());
    if (right_plots.tellp() > 0)
      panels.push_back(right.str() + right_plots.str());
    else if (lambda_c_panel)
      panels.push_back("set title 'no flowing runs with friction bracketing lambda = 1e-2 within a decade, or within half a "
                       "decade of it' noenhanced font ',9'\nunset logscale y\nset yrange [0:1]\nplot -1 notitle\nset yrange [*:*]");
    if (one_lambda_panel) panels.push_back(third.str() + third_plots.str());
    f.width = std::max(900, 450 * static_cast<int>(panels.size()));
    body << "set key below font ',8' noenhanced\nset multiplot layout 1," << panels.size();
    if (families.size() == 1) body << " title " << gnuplot_string(families.begin()->first) << " font ',10' noenhanced";
    body << "\n";
    for (const std::string& panel : panels) body << panel << "\n";
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir,
                "needs beta(lambda) groups that differ only in the hopper angle theta_w, at two or more angles, with a "
                "crossover fit or a force ratio near lambda = 1e-2 (Fig. 6)");
}

}  // namespace beverloo::figures
