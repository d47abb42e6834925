// Q versus w per series, with the fitted Beverloo curve Q = C (w - k)^beta: the continuous flows,
// and (paper Fig. 8c) the draining hoppers' Q = c0 t0, measured and simulated, on their own.
#include <algorithm>
#include <sstream>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/fit.h"

namespace beverloo::figures {

void plot_q_vs_w(Figure& f, const std::vector<const Series*>& list) {
  const int n = static_cast<int>(list.size());
  int k = 0;
  for (const Series* sp : list) {
    const Series& s = *sp;
    const std::string style = series_style(k++, n);
    bool any = false;
    for (const auto& p : s.points) any |= p.flowing();
    if (!any) continue;
    // converged points and those that stopped at t_max (Q with a larger error than asked): the
    // second drawn open, so that a reader sees which points the fit leans on less
    for (const bool limited : {false, true}) {
      std::ostringstream rows;
      for (const auto& p : s.points)
        if (p.flowing() && (p.time_limited > 0) == limited) rows << num(p.w) << " " << num(p.Q) << " " << num(p.Q_err) << "\n";
      if (rows.str().empty()) continue;
      const int points = f.begin_block(s.label + (limited ? ": w Q Q_err (stopped at t_max)" : ": w Q Q_err (converged)"));
      f.data << rows.str();
      const std::string colour = style.substr(0, style.find(" pt"));
      f.plots.push_back("DATA index " + std::to_string(points) + " using 1:2:3 with yerrorbars " +
                        (limited ? colour + " pt 6" : style) + " title " +
                        gnuplot_string(s.label + (limited ? " (stopped at t_max)" : "")));
    }
    if (s.fit) {
      const int curve = f.begin_block(s.label + ": fitted curve w Q");
      const double lo = std::max(s.fit->k + 1e-3, s.points.front().w - 0.5), hi = s.points.back().w + 0.5;
      for (int i = 0; i <= 100; ++i) {
        const double w = lo + (hi - lo) * i / 100;
        f.data << num(w) << " " << num(beverloo_model(w, s.fit->C, s.fit->k, s.fit->beta)) << "\n";
      }
      f.plots.push_back("DATA index " + std::to_string(curve) + " using 1:2 with lines " + style + " notitle");
    }
  }
}

ReportFigure q_vs_w(const FigureContext& c) {
  Figure f("Q_vs_w", "Flow rate Q versus orifice width w, with fits Q = C (w - k)^beta", "w / sigma_avg", "Q / Q_0");
  std::vector<const Series*> list;
  for (const Series& s : c.fits.series)
    if (!s.rate_is_c0()) list.push_back(&s);
  plot_q_vs_w(f, list);
  return finish(f, c.dir, "no finished jobs");
}

ReportFigure drain_q_vs_w(const FigureContext& c) {
  Figure f("drain_Q_vs_w", "Draining hoppers: Q = c0 t0 versus w, measured and simulated (paper Fig. 8c)", "w / sigma_avg",
           "Q = c0 t0, with dN/dt = -c0 N^(1/2)");
  std::vector<const Series*> list;
  for (const Series& s : c.fits.series)
    if (s.rate_is_c0()) list.push_back(&s);
  plot_q_vs_w(f, list);
  return finish(f, c.dir, "no draining-hopper series (jobs with reinject = false, or `beverloo experiment import`)");
}

}  // namespace beverloo::figures
