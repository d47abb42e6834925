// The paper's Fig. 6 in its own form, beside the exponents of beta_vs_lambda (its panel a):
// (left) lambda_c against the hopper angle theta_w for the beta(lambda) groups that differ only
// in theta_w, both crossover fits (the paper's fixed plateaus, and free ones), with the paper's
// stated values in grey (5e-2 at 90 deg, 6e-3 at 20 deg, a plateau ~5e-3 for theta_w <= 30 deg);
// (right, its panel b) the ratio of the mean drag force to the mean friction force on a particle,
// |F_zeta| / |F_mu|, against theta_w at the paper's lambda = 1e-2: each series' mean over its
// runs (error: their standard error), interpolated in log-log between the two series of the group
// that bracket 1e-2, so that every angle is read at the same lambda. Never rescaled.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/crossover_groups.h"
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

/// The paper's lambda for the force ratio (Fig. 6b); how far (in decades) each of the two series
/// that bracket it may lie for an interpolation, and how far the nearest series may lie when
/// the group's lambdas do not bracket it.
constexpr double kForceRatioLambda = 1e-2;
constexpr double kForceRatioBracketDecades = 1.0;
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

/// A group's force ratio read at the paper's lambda, and the lambdas it was read from.
struct RatioAtPaperLambda {
  double lambda = NAN;  // kForceRatioLambda when bracketed (or hit), else the nearest series' lambda
  double mean = NAN, err = NAN;
  double lambda_below = NAN, lambda_above = NAN;
  int runs = 0;
};

/// The ratio is close to proportional to lambda (|F_zeta| = zeta |v|, |F_mu| = mu x a contact
/// force that changes slowly with lambda), so it is interpolated linearly in log ratio against
/// log lambda between the bracketing series; its relative error is propagated from theirs.
/// Reading each angle at its own nearest lambda instead biased the comparison by the ratio of
/// those lambdas (0.010 against 0.018 in the SP campaign).
std::optional<RatioAtPaperLambda> ratio_at_paper_lambda(db::Database& db, const Crossover& g) {
  auto decades = [](double lambda) { return std::log10(lambda / kForceRatioLambda); };
  std::vector<Ratio> below, above;  // flowing series with a ratio, on each side of 1e-2
  for (const Series* s : g.finite) {
    const double off = decades(s->lambda);
    if (std::fabs(off) > kForceRatioBracketDecades) continue;
    const Ratio r = force_ratio(db, *s);
    if (r.runs == 0) continue;
    (off <= 0 ? below : above).push_back(r);
  }
  auto closest = [&](const std::vector<Ratio>& side) {
    return *std::min_element(side.begin(), side.end(), [&](const Ratio& a, const Ratio& b) {
      return std::fabs(decades(a.lambda)) < std::fabs(decades(b.lambda));
    });
  };
  RatioAtPaperLambda out;
  if (!below.empty() && !above.empty()) {
    const Ratio lo = closest(below), hi = closest(above);
    out.lambda = kForceRatioLambda;
    out.lambda_below = lo.lambda;
    out.lambda_above = hi.lambda;
    out.runs = lo.runs + hi.runs;
    for (const Ratio& at : {lo, hi})
      if (std::fabs(decades(at.lambda)) < 1e-9) {  // a series at the paper's lambda itself
        out.mean = at.mean, out.err = at.err, out.runs = at.runs;
        out.lambda_below = out.lambda_above = at.lambda;
        return out;
      }
    const double t = -decades(lo.lambda) / (decades(hi.lambda) - decades(lo.lambda));
    out.mean = std::exp((1 - t) * std::log(lo.mean) + t * std::log(hi.mean));
    out.err = out.mean * std::hypot((1 - t) * lo.err / lo.mean, t * hi.err / hi.mean);
    return out;
  }
  const std::vector<Ratio>& side = below.empty() ? above : below;
  if (side.empty()) return std::nullopt;
  const Ratio nearest = closest(side);
  if (std::fabs(decades(nearest.lambda)) > kForceRatioMaxDecades) return std::nullopt;
  out.lambda = out.lambda_below = out.lambda_above = nearest.lambda;
  out.mean = nearest.mean, out.err = nearest.err, out.runs = nearest.runs;
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
  for (auto& [key, by_theta] : angle_families(c.fits.crossovers, /*fitted_only=*/true))
    by_key[key] = Family{family_name(*by_theta.begin()->second->finite.front()), std::move(by_theta)};
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
    right << "set title 'force ratio at lambda = 1e-2 (log-log between the bracketing lambdas)' noenhanced font ',9'\nunset logscale y\nset format y '%g'\n"
          << "set xrange [0:100]\nset xlabel 'theta_w (deg)'\nset ylabel '|F_zeta| / |F_mu|' noenhanced\n";
    bool any_ratio = false;
    std::ostringstream right_plots;
    int k = 0;
    for (const auto& [family, by_theta] : families) {
      const std::string style = series_style(k++, static_cast<int>(families.size()));
      // the bars: lambda_c times and over 10^sigma, sigma the larger of the fit's error of
      // log10 lambda_c and its spread over the replicas' own fits (as the claims table judges it)
      auto row = [&](double theta, const CrossoverFit& fit, const Crossover::ReplicaSpread& spread) {
        const double sigma = log10_lambda_c_sigma(fit, spread);
        f.data << num(theta) << " " << num(fit.lambda_c) << " " << num(fit.lambda_c_err) << " "
               << num(spread.log10_lambda_c) << " " << num(fit.lambda_c * std::pow(10.0, -sigma)) << " "
               << num(fit.lambda_c * std::pow(10.0, sigma)) << "\n";
      };
      const std::string columns = ": theta_w lambda_c lambda_c_err log10_lambda_c_replica_spread bar_low bar_high";
      const int fixed = f.begin_block(family + columns + " (the paper's fixed plateaus)");
      for (const auto& [theta, g] : by_theta)
        if (g->fit) row(theta, *g->fit, g->spread);
      const int free_block = f.begin_block(family + columns + " (plateaus free)");
      for (const auto& [theta, g] : by_theta)
        if (g->fit_free) row(theta, *g->fit_free, g->spread_free);
      left << ", \\\n     DATA index " << fixed << " using 1:2:5:6 with yerrorlines " << style << " title "
           << gnuplot_string(family + ", plateaus 3/2, 1/2") << ", \\\n     DATA index " << free_block
           << " using 1:2:5:6 with yerrorlines dt 2 " << style.substr(0, style.find(" pt")) << " pt 4 title " << gnuplot_string(family + ", plateaus free");
      const int ratio =
          f.begin_block(family + ": theta_w force_ratio force_ratio_err lambda runs lambda_below lambda_above");
      for (const auto& [theta, g] : by_theta) {
        const auto r = ratio_at_paper_lambda(c.db, *g);
        if (!r) continue;
        any_ratio = true;
        f.data << num(theta) << " " << num(r->mean) << " " << num(r->err) << " " << num(r->lambda) << " " << r->runs
               << " " << num(r->lambda_below) << " " << num(r->lambda_above) << "\n";
      }
      right_plots << (right_plots.tellp() > 0 ? ", \\\n     " : "plot ") << "DATA index " << ratio
                  << " using 1:2:3 with yerrorlines " << style << " title " << gnuplot_string(family);
    }
    std::ostringstream body;
    body << "set key below font ',8' noenhanced\nset multiplot layout 1,2\n" << left.str() << "\n";
    if (any_ratio)
      body << right.str() << right_plots.str() << "\n";
    else
      body << "set title 'no flowing runs with friction bracketing lambda = 1e-2 within a decade, or within half a decade of it' noenhanced font ',9'\n"
           << "unset logscale y\nset yrange [0:1]\nplot -1 notitle\n";
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir,
                "needs beta(lambda) groups with a crossover fit at two or more hopper angles theta_w, the rest equal (Fig. 6)");
}

}  // namespace beverloo::figures
