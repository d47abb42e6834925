// The paper's Fig. 6 in its own form, beside the exponents of beta_vs_lambda (its panel a):
// (left) lambda_c against the hopper angle theta_w for the beta(lambda) groups that differ only
// in theta_w, both crossover fits (the paper's fixed plateaus, and free ones), with the paper's
// stated values in grey (5e-2 at 90 deg, 6e-3 at 20 deg, a plateau ~5e-3 for theta_w <= 30 deg);
// (right, its panel b) the ratio of the mean drag force to the mean friction force on a particle,
// |F_zeta| / |F_mu|, against theta_w at the group's lambda nearest 1e-2 (the paper's lambda),
// averaged over that series' runs (error: their standard error). Never rescaled.
#include <algorithm>
#include <cmath>
#include <map>

#include "core/text_escape.h"
#include "figure.h"
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

/// The paper's lambda for the force ratio (Fig. 6b) and how far (in decades) a group's nearest
/// lambda may be from it.
constexpr double kForceRatioLambda = 1e-2;
constexpr double kForceRatioMaxDecades = 0.5;

struct Ratio {
  double lambda = NAN, mean = NAN, err = NAN;
  int runs = 0;
};

/// The mean |F_zeta| / |F_mu| over a series' runs that ended flowing with a finite ratio.
Ratio force_ratio(db::Database& db, const Series& s) {
  db::Statement st = db.prepare("SELECT force_ratio FROM runs WHERE key = ?1 AND force_ratio IS NOT NULL AND Q > 0");
  std::vector<double> values;
  for (const std::string& key : s.job_keys) {
    st.bind(1, key);
    while (st.step()) {
      const double r = st.get_double(0);
      if (std::isfinite(r) && r > 0) values.push_back(r);
    }
    st.reset();
  }
  Ratio out;
  out.lambda = s.lambda;
  out.runs = static_cast<int>(values.size());
  if (values.empty()) return out;
  out.mean = 0;
  for (double v : values) out.mean += v / values.size();
  out.err = values.size() > 1 ? sample_sd(values) / std::sqrt(values.size()) : 0;
  return out;
}

}  // namespace

ReportFigure lambda_c_vs_theta(const FigureContext& c) {
  Figure f("lambda_c_vs_theta",
           "Crossover lambda_c and the drag-to-friction force ratio versus the hopper angle theta_w (the paper's Fig. 6)",
           "theta_w (deg)", "lambda_c");
  // Families: the groups that differ only in theta_w (Crossover::angle_family), so that one
  // angle holds exactly one group of a family; each family -> theta_w -> its group.
  struct Family {
    std::string name;
    std::map<double, const Crossover*> by_theta;
  };
  std::map<std::string, Family> by_key;
  for (const Crossover& g : c.fits.crossovers) {
    if (g.finite.empty() || (!g.fit && !g.fit_free)) continue;
    const Series& s = *g.finite.front();
    if (s.theta_left != s.theta_right) continue;
    Family& family = by_key[g.angle_family];
    family.name = family_name(s);
    family.by_theta.emplace(s.theta_left, &g);
  }
  // by name (a stable order for the figure), a name shared by families made unique by their key
  std::map<std::string, int> name_uses;
  for (const auto& [key, family] : by_key)
    if (family.by_theta.size() >= 2) ++name_uses[family.name];
  std::map<std::string, std::map<double, const Crossover*>> families;
  for (const auto& [key, family] : by_key)
    if (family.by_theta.size() >= 2)
      families.emplace(name_uses[family.name] > 1 ? family.name + " [" + key.substr(0, 8) + "]" : family.name,
                       family.by_theta);
  if (!families.empty()) {
    std::ostringstream left, right;
    left << "set title 'lambda_c (midpoint of beta(lambda))' noenhanced font ',9'\nset logscale y\n"
         << "set format y '10^{%L}'\nset xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel 'lambda_c'\n";
    // the paper's values: 5e-2 at 90 deg, ~6e-3 at 20 deg, a plateau ~5e-3 below 30 deg
    const int paper = f.begin_block("the paper: theta_w lambda_c");
    f.data << "90 0.05\n20 0.006\n";
    const int plateau = f.begin_block("the paper's plateau: theta_w lambda_c");
    f.data << "0 0.005\n30 0.005\n";
    left << "plot DATA index " << paper << " using 1:2 with points pt 6 ps 2 lc rgb 'gray50' title 'paper: 5e-2 (90), 6e-3 (20)', \\\n"
         << "     DATA index " << plateau << " using 1:2 with lines dt 3 lc rgb 'gray50' title 'paper: plateau ~5e-3'";
    right << "set title 'force ratio at lambda nearest 1e-2' noenhanced font ',9'\nunset logscale y\nset format y '%g'\n"
          << "set xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel '|F_zeta| / |F_mu|' noenhanced\n";
    bool any_ratio = false;
    std::ostringstream right_plots;
    int k = 0;
    for (const auto& [family, by_theta] : families) {
      const std::string style = series_style(k++, static_cast<int>(families.size()));
      const int fixed = f.begin_block(family + ": theta_w lambda_c lambda_c_err (the paper's fixed plateaus)");
      for (const auto& [theta, g] : by_theta)
        if (g->fit) f.data << num(theta) << " " << num(g->fit->lambda_c) << " " << num(g->fit->lambda_c_err) << "\n";
      const int free_block = f.begin_block(family + ": theta_w lambda_c lambda_c_err (plateaus free)");
      for (const auto& [theta, g] : by_theta)
        if (g->fit_free) f.data << num(theta) << " " << num(g->fit_free->lambda_c) << " " << num(g->fit_free->lambda_c_err) << "\n";
      left << ", \\\n     DATA index " << fixed << " using 1:2:3 with yerrorlines " << style << " title "
           << gnuplot_string(family + ", plateaus 3/2, 1/2") << ", \\\n     DATA index " << free_block
           << " using 1:2:3 with yerrorlines dt 2 " << style.substr(0, style.find(" pt")) << " pt 4 title " << gnuplot_string(family + ", plateaus free");
      const int ratio = f.begin_block(family + ": theta_w force_ratio force_ratio_err lambda runs");
      for (const auto& [theta, g] : by_theta) {
        auto decades_off = [](const Series* s) { return std::fabs(std::log10(s->lambda / kForceRatioLambda)); };
        const Series* nearest = *std::min_element(g->finite.begin(), g->finite.end(),
                                                  [&](const Series* a, const Series* b) { return decades_off(a) < decades_off(b); });
        if (decades_off(nearest) > kForceRatioMaxDecades) continue;
        const Ratio r = force_ratio(c.db, *nearest);
        if (r.runs == 0) continue;
        any_ratio = true;
        f.data << num(theta) << " " << num(r.mean) << " " << num(r.err) << " " << num(r.lambda) << " " << r.runs << "\n";
      }
      right_plots << (right_plots.tellp() > 0 ? ", \\\n     " : "plot ") << "DATA index " << ratio
                  << " using 1:2:3 with yerrorlines " << style << " title " << gnuplot_string(family);
    }
    std::ostringstream body;
    body << "set key below font ',8' noenhanced\nset multiplot layout 1,2\n" << left.str() << "\n";
    if (any_ratio)
      body << right.str() << right_plots.str() << "\n";
    else
      body << "set title 'no flowing run with friction at lambda within half a decade of 1e-2' noenhanced font ',9'\n"
           << "unset logscale y\nset yrange [0:1]\nplot -1 notitle\n";
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir,
                "needs beta(lambda) groups with a crossover fit at two or more hopper angles theta_w, the rest equal (Fig. 6)");
}

}  // namespace beverloo::figures
