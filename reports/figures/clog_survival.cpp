// Clogging as a result: per w of the series in which some run clogged, the probability that a
// flow is still running at t, S(t), by Kaplan-Meier over the replicas (reports/survival.h),
// with Greenwood's one-sigma band; at most eight curves (the rest are in clog_statistics).
#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {

ReportFigure clog_survival(const FigureContext& c) {
  Figure f("clog_survival", "Still flowing at t: Kaplan-Meier over the replicas (band: one Greenwood sigma)",
           "t / t0", "S(t), the fraction of runs not yet clogged", "set yrange [0:1.05]\n");
  struct Curve {
    std::string label;
    const Series::ClogPoint* point;
  };
  std::vector<Curve> curves;
  for (const Series& s : c.fits.series)
    for (const Series::ClogPoint& p : s.clog_points)
      if (p.km.clogs > 0 && curves.size() < 8) curves.push_back({s.label + ", w = " + num(p.w), &p});
  const int n = static_cast<int>(curves.size());
  for (int k = 0; k < n; ++k) {
    const KaplanMeier& km = curves[k].point->km;
    const int block = f.begin_block(curves[k].label + ": t S S_err (steps)");
    // a step function: S = 1 from 0 to the first clog, then each step, held to t_max
    double S = 1, err = 0, t_prev = 0;
    f.data << "0 1 0\n";
    for (std::size_t i = 0; i < km.time.size(); ++i) {
      f.data << num(km.time[i]) << " " << num(S) << " " << num(err) << "\n";
      S = km.survival[i];
      err = km.survival_err[i];
      f.data << num(km.time[i]) << " " << num(S) << " " << num(err) << "\n";
      t_prev = km.time[i];
    }
    const double end = curves[k].point->t_max > t_prev ? curves[k].point->t_max : t_prev;
    f.data << num(end) << " " << num(S) << " " << num(err) << "\n";
    const std::string style = series_style(k, n);
    const std::string line = style.substr(0, style.find(" pt"));
    f.plots.push_back("DATA index " + std::to_string(block) + " using 1:($2-$3):($2+$3) with filledcurves " + line +
                      " fs transparent solid 0.15 notitle");
    f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2 with lines " + line + " title " +
                      gnuplot_string(curves[k].label));
  }
  return finish(f, c.dir, "needs a series in which some run clogged (replicas at w near k)");
}

}  // namespace beverloo::figures
