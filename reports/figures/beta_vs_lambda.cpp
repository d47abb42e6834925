// beta versus lambda per crossover group, with the fitted sigmoid (the paper's fixed plateaus,
// and free ones), the two limits, and the paper's stated values (its plateaus d - 1/2 and
// d - 3/2 and lambda_c ~ 0.05 in 2D, ~ 0.07 in 3D) in grey; never rescaled (docs/paper.md).
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/fit.h"
#include "reports/number_format.h"

namespace beverloo::figures {

// The frame is the paper's (its plateaus d - 1/2 and d - 3/2, kFrameMargin either side) widened
// to every exponent that is measured, with its error bar, the limits' included. An exponent
// with an error above kFrameBetaErr (beta unknown by more than the crossover's whole
// half-height) does not widen it: one such series (the DP campaign's beta = 6.2 +- 6.5 at 20
// deg, lambda = 1e-3) flattened every sigmoid into a line. It is left beyond the frame and
// counted.
constexpr double kFrameBetaErr = 0.5, kFrameMargin = 0.2;

std::optional<BetaFrame> beta_vs_lambda_frame(const CampaignFits& fits) {
  double lo = INFINITY, hi = -INFINITY;
  auto widen = [&](const Series* s) {
    if (s && s->fit && s->fit->beta_err <= kFrameBetaErr)
      lo = std::min(lo, s->fit->beta - s->fit->beta_err), hi = std::max(hi, s->fit->beta + s->fit->beta_err);
  };
  for (const Crossover& g : fits.crossovers) {
    if (g.finite.empty()) continue;
    lo = std::min(lo, g.dimension - 1.5), hi = std::max(hi, g.dimension - 0.5);
    for (const Series* s : g.finite) widen(s);
    widen(g.limit0), widen(g.limit_inf);
  }
  if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
  BetaFrame frame{lo - kFrameMargin, hi + kFrameMargin, 0};
  for (const Crossover& g : fits.crossovers)
    for (const Series* s : g.finite)
      if (s->fit && (s->fit->beta < frame.lo || s->fit->beta > frame.hi)) ++frame.beyond;
  return frame;
}

ReportFigure beta_vs_lambda(const FigureContext& c) {
  Figure f("beta_vs_lambda", "Exponent beta versus lambda = zeta/mu, with beta = d - 1 - tanh[log10(lambda/lambda_c)/b]/2",
           "lambda (dimensionless)", "beta", "set logscale x\nset format x '10^{%L}'\n");
  int n = 0;
  for (const Crossover& g : c.fits.crossovers) n += !g.finite.empty();
  if (const std::optional<BetaFrame> frame = beta_vs_lambda_frame(c.fits)) {
    f.extra += "set yrange [" + num(frame->lo) + ":" + num(frame->hi) + "]\n";
    if (frame->beyond > 0)
      f.extra += "set label " +
                 gnuplot_string(std::to_string(frame->beyond) + (frame->beyond == 1 ? " exponent" : " exponents") +
                                " with an error above " + format_value(kFrameBetaErr, 2) + " beyond the frame (beverloo_fits.md)") +
                 " at graph 0.02, graph 0.04 font ',9' noenhanced\n";
  }
  int k = 0;
  bool paper_drawn[4] = {false, false, false, false};
  for (const Crossover& g : c.fits.crossovers) {
    if (g.finite.empty()) continue;
    if (g.dimension >= 2 && g.dimension <= 3 && !paper_drawn[g.dimension]) {
      paper_drawn[g.dimension] = true;
      const double d = g.dimension, lambda_c = g.dimension == 2 ? 0.05 : 0.07;
      char label[96];
      std::snprintf(label, sizeof label, "paper (%dD): beta = %.1f, %.1f; lambda_c ~ %.2g", g.dimension, d - 0.5, d - 1.5,
                    lambda_c);
      f.extra += "set arrow from " + num(lambda_c) + ", graph 0 to " + num(lambda_c) +
                 ", graph 1 nohead " + kPaperLineStyle + "\n";
      f.plots.push_back(num(d - 0.5) + " with lines " + kPaperLineStyle + " title " + gnuplot_string(label));
      f.plots.push_back(num(d - 1.5) + " with lines " + kPaperLineStyle + " notitle");
    }
    const std::string style = series_style(k++, n);
    if (g.fitted_points() > 0) {  // (no empty block: gnuplot would have nothing to draw)
      const int points = f.begin_block(g.label + ": lambda beta beta_err");
      for (const Series* s : g.finite)
        if (g.takes(s)) f.data << num(s->lambda) << " " << num(s->fit->beta) << " " << num(s->fit->beta_err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(points) + " using 1:2:3 with yerrorbars " + style + " title " +
                        gnuplot_string(g.label));
    }
    if (!g.no_beverloo_law.empty()) {  // drawn with open circles, but not in the sigmoid's fit
      const int left_out = f.begin_block(g.label + ": no Beverloo law (" + no_beverloo_law_rule() + "), not fitted: lambda beta beta_err");
      for (const Series* s : g.no_beverloo_law)
        f.data << num(s->lambda) << " " << num(s->fit->beta) << " " << num(s->fit->beta_err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(left_out) + " using 1:2:3 with yerrorbars " +
                        style.substr(0, style.find(" pt")) + " pt 6 title " +
                        gnuplot_string(g.label + ": " + no_beverloo_law_rule() + ", not in the sigmoid's fit"));
    }
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
    if (g.fit_free) {
      const CrossoverFit& ff = *g.fit_free;
      const int curve = f.begin_block(g.label + ": sigmoid with free plateaus lambda beta");
      const double lo = std::log10(g.finite.front()->lambda) - 1, hi = std::log10(g.finite.back()->lambda) + 1;
      for (int i = 0; i <= 100; ++i) {
        const double l = std::pow(10.0, lo + (hi - lo) * i / 100);
        const double step = 0.5 * (1 - std::tanh(std::log10(l / ff.lambda_c) / ff.b));
        f.data << num(l) << " " << num(ff.beta_inf + (ff.beta_0 - ff.beta_inf) * step) << "\n";
      }
      char label[128];
      std::snprintf(label, sizeof label, "fit, plateaus free (%.2f, %.2f), lambda_c = %.2g", ff.beta_0, ff.beta_inf,
                    ff.lambda_c);
      f.plots.push_back("DATA index " + std::to_string(curve) + " using 1:2 with lines dt 5 " +
                        style.substr(0, style.find(" pt")) + " title " + gnuplot_string(label));
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
