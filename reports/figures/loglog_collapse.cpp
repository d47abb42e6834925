// The collapse log10(Q/C) versus log10(w - k) with the reference slopes 1/2, 3/2, 5/2: each
// series' own fit puts its points on a line of slope beta.
#include <cmath>

#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {

void plot_collapse(Figure& f, const std::vector<const Series*>& list) {
  int n = 0;
  for (const Series* s : list) n += s->fit.has_value();
  int k = 0;
  for (const Series* sp : list) {
    const Series& s = *sp;
    if (!s.fit) continue;
    const int block = f.begin_block(s.label + ": log10(w - k) log10(Q/C) error (the point's own: Q_err / (Q ln 10))");
    for (const auto& p : s.points)
      if (p.flowing() && p.w > s.fit->k)
        f.data << num(std::log10(p.w - s.fit->k)) << " " << num(std::log10(p.Q / s.fit->C)) << " "
               << num(p.Q_err / (p.Q * std::log(10.0))) << "\n";
    char beta[64];
    std::snprintf(beta, sizeof beta, " (beta %.2f)", s.fit->beta);
    f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2:3 with yerrorbars " + series_style(k++, n) +
                      " title " + gnuplot_string(s.label + beta));
  }
}

ReportFigure loglog_collapse(const FigureContext& c) {
  Figure f("loglog_collapse", "Collapse: log10(Q/C) versus log10(w - k), reference slopes 1/2, 3/2, 5/2",
           "log10((w - k) / sigma_avg)", "log10(Q / C)");
  std::vector<const Series*> list;
  for (const Series& s : c.fits.series)
    if (!s.rate_is_c0()) list.push_back(&s);
  plot_collapse(f, list);
  f.plots.push_back("0.5*x with lines dt 2 lc rgb 'gray40' title 'slope 1/2'");
  f.plots.push_back("1.5*x with lines dt 3 lc rgb 'gray40' title 'slope 3/2'");
  f.plots.push_back("2.5*x with lines dt 4 lc rgb 'gray40' title 'slope 5/2'");
  return finish(f, c.dir, "no series could be fitted (at least 4 flowing w per series)");
}

ReportFigure drain_collapse(const FigureContext& c) {
  Figure f("drain_collapse", "Draining hoppers: log10(Q/C) versus log10(w - k), slope 1/2 (paper Fig. 8d)",
           "log10((w - k) / sigma_avg)", "log10(Q / C)");
  std::vector<const Series*> list;
  for (const Series& s : c.fits.series)
    if (s.rate_is_c0()) list.push_back(&s);
  plot_collapse(f, list);
  f.plots.push_back("0.5*x with lines dt 2 lc rgb 'gray40' title 'slope 1/2'");
  return finish(f, c.dir, "no draining-hopper series could be fitted (at least 4 widths per series)");
}

}  // namespace beverloo::figures
