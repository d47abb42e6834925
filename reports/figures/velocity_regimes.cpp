// The paper's Fig. 5 in its own form: v_g(h) on the centre line in the three regimes of one
// crossover group, friction only (lambda -> 0), the finite lambda nearest the fitted lambda_c
// (the free-plateau fit's where it has one among the measured lambdas), and drag only (lambda
// -> inf), one curve per w (replicas averaged at each h; band: their standard error, or the
// run's own error for one replica). Each panel's title gives the
// exponent of v_g(h = 0) ~ w^x over the panel's widths (log-log least squares on the means):
// the paper's claim is x > 0 for lambda -> 0, x < 0 for lambda -> inf, weak near lambda_c.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {
namespace {

struct Profile {
  std::vector<double> h, v, err;
};

/// Per w, the replicas' v_g(h) averaged (only heights every replica has).
std::map<double, Profile> pooled_profiles(db::Database& db, const Series& s) {
  std::map<double, std::map<double, std::vector<std::pair<double, double>>>> by_w;  // w -> h -> (v, err)
  db::Statement st = db.prepare(
      "SELECT j.w, p.h, p.v_g, p.v_g_err FROM velocity_profiles p JOIN jobs j ON j.key = p.job_key WHERE p.job_key = ?1");
  std::map<double, int> replicas;
  for (const std::string& key : s.job_keys) {
    st.bind(1, key);
    double w = NAN;
    while (st.step()) {
      w = st.get_double(0);
      by_w[w][st.get_double(1)].push_back({st.get_double(2), st.get_double(3)});
    }
    st.reset();
    if (!std::isnan(w)) ++replicas[w];
  }
  std::map<double, Profile> out;
  for (const auto& [w, heights] : by_w) {
    Profile& p = out[w];
    for (const auto& [h, vals] : heights) {
      if (static_cast<int>(vals.size()) != replicas[w]) continue;
      const double n = vals.size();
      double mean = 0;
      for (const auto& v : vals) mean += v.first / n;
      double err = vals.front().second;
      if (vals.size() > 1) {
        double ss = 0;
        for (const auto& v : vals) ss += (v.first - mean) * (v.first - mean);
        err = std::sqrt(ss / (n - 1) / n);
      }
      p.h.push_back(h);
      p.v.push_back(mean);
      p.err.push_back(err);
    }
  }
  return out;
}

/// d ln v_g(0) / d ln w over the widths (NaN below two widths or without h = 0).
double exponent_at_orifice(const std::map<double, Profile>& profiles) {
  std::vector<double> x, y;
  for (const auto& [w, p] : profiles)
    if (!p.h.empty() && p.h.front() == 0 && p.v.front() > 0 && w > 0) {
      x.push_back(std::log(w));
      y.push_back(std::log(p.v.front()));
    }
  if (x.size() < 2) return NAN;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / x.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

}  // namespace

ReportFigure velocity_regimes(const FigureContext& c) {
  Figure f("velocity_regimes",
           "Paper Fig. 5: v_g(h) on the centre line in the three regimes, one curve per w",
           "h / sigma_avg", "v_g / (sigma_avg / t0)");
  const Crossover* group = nullptr;
  for (const Crossover& g : c.fits.crossovers)
    if (g.limit0 && g.limit_inf && !g.finite.empty()) {
      group = &g;
      break;
    }
  if (group) {
    // the finite lambda nearest the data's midpoint on a log scale: the free-plateau fit's
    // lambda_c where it has one inside the measured lambdas (the paper's fixed plateaus put
    // lambda_c where a curve from d - 1/2 to d - 3/2 crosses d - 1, which is not the data's
    // crossover when their plateaus lie elsewhere: the text set's Fig. 4a, 0.18 against
    // 0.0081), else the paper's fit's, else the middle series
    const Series* middle = group->finite[group->finite.size() / 2];
    double lo = INFINITY, hi = 0;
    for (const Series* s : group->finite) lo = std::min(lo, s->lambda), hi = std::max(hi, s->lambda);
    auto inside = [&](const std::optional<CrossoverFit>& fit) { return fit && fit->lambda_c >= lo && fit->lambda_c <= hi; };
    const std::optional<CrossoverFit>* midpoint = inside(group->fit_free) ? &group->fit_free
                                                  : inside(group->fit)    ? &group->fit
                                                                          : nullptr;
    std::string middle_name;
    if (midpoint) {
      const double lambda_c = (*midpoint)->lambda_c;
      double best = INFINITY;
      for (const Series* s : group->finite)
        if (const double d = std::fabs(std::log10(s->lambda / lambda_c)); d < best) best = d, middle = s;
      middle_name = " (lambda_c = " + format_lambda(lambda_c) +
                    (midpoint == &group->fit_free ? ", plateaus free)" : ", the paper's plateaus)");
    }
    const std::pair<const Series*, std::string> panels[3] = {
        {group->limit0, "lambda -> 0"},
        {middle, "lambda = " + format_lambda(middle->lambda) + middle_name},
        {group->limit_inf, "lambda -> inf"}};
    std::ostringstream body;
    body << "set multiplot layout 1,3\nset key top right font ',7'\n";
    for (const auto& [series, name] : panels) {
      const std::map<double, Profile> profiles = pooled_profiles(c.db, *series);
      const double x = exponent_at_orifice(profiles);
      std::ostringstream title;
      title << name;
      if (!std::isnan(x)) title << ": v_g(0) ~ w^{" << table_number(x, 2) << "}";
      body << "set title " << gnuplot_string(title.str()) << " noenhanced font ',9'\nplot ";
      const int n = static_cast<int>(profiles.size());
      int k = 0;
      for (const auto& [w, p] : profiles) {
        const int block = f.begin_block(name + ", w = " + num(w) + ": h v_g v_g_err");
        for (std::size_t i = 0; i < p.h.size(); ++i) f.data << num(p.h[i]) << " " << num(p.v[i]) << " " << num(p.err[i]) << "\n";
        const std::string style = series_style(n - 1 - k, n), colour = style.substr(0, style.find(" pt"));
        body << (k ? ", \\\n     " : "") << "DATA index " << block
             << " using 1:($2-$3):($2+$3) with filledcurves fs transparent solid 0.25 noborder " << colour << " notitle, \\\n"
             << "     DATA index " << block << " using 1:2 with lines lw 1.5 " << colour << " title "
             << gnuplot_string("w = " + num(w));
        ++k;
      }
      if (n == 0) body << "NaN notitle";
      body << "\n";
    }
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir,
                "needs a crossover group: series differing only in lambda, with both limits (lambda = 0 and inf) and a "
                "finite lambda, and their velocity profiles");
}

}  // namespace beverloo::figures
