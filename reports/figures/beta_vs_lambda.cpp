// beta versus lambda per crossover group, with the fitted sigmoid and the two limits.
#include <cmath>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/fit.h"

namespace beverloo::figures {

ReportFigure beta_vs_lambda(const FigureContext& c) {
  Figure f("beta_vs_lambda", "Exponent beta versus lambda = zeta/mu, with beta = d - 1 - tanh[log10(lambda/lambda_c)/b]/2",
           "lambda (dimensionless)", "beta", "set logscale x\nset format x '10^{%L}'\n");
  int n = 0;
  for (const Crossover& g : c.fits.crossovers) n += !g.finite.empty();
  int k = 0;
  for (const Crossover& g : c.fits.crossovers) {
    if (g.finite.empty()) continue;
    const std::string style = series_style(k++, n);
    const int points = f.begin_block(g.label + ": lambda beta beta_err");
    for (const Series* s : g.finite) f.data << num(s->lambda) << " " << num(s->fit->beta) << " " << num(s->fit->beta_err) << "\n";
    f.plots.push_back("DATA index " + std::to_string(points) + " using 1:2:3 with yerrorbars " + style + " title " +
                      gnuplot_string(g.label));
    if (g.fit) {
      const int curve = f.begin_block(g.label + ": sigmoid lambda beta");
      const double lo = std::log10(g.finite.front()->lambda) - 1, hi = std::log10(g.finite.back()->lambda) + 1;
      for (int i = 0; i <= 100; ++i) {
        const double l = std::pow(10.0, lo + (hi - lo) * i / 100);
        f.data << num(l) << " " << num(crossover_model(g.dimension, l, g.fit->lambda_c, g.fit->b)) << "\n";
      }
      char label[96];
      std::snprintf(label, sizeof label, "fit, lambda_c = %.2g", g.fit->lambda_c);
      f.plots.push_back("DATA index " + std::to_string(curve) + " using 1:2 with lines " + style + " title " + gnuplot_string(label));
    }
    for (const auto& [lim, name, dash] :
         {std::tuple{g.limit0, "lambda = 0", 2}, std::tuple{g.limit_inf, "lambda = inf", 4}})
      if (lim && lim->fit) {
        char value[64];
        std::snprintf(value, sizeof value, "%s: beta %.2f", name, lim->fit->beta);
        f.plots.push_back(num(lim->fit->beta) + " with lines dt " + std::to_string(dash) + " " +
                          style.substr(0, style.find(" pt")) + " title " + gnuplot_string(value));
      }
  }
  return finish(f, c.dir, "needs series at several finite lambda > 0 (a lambda sweep)");
}

}  // namespace beverloo::figures
