// N(t) of a few draining-hopper runs (imported: measured or simulated) with the fitted law
// dN/dt = -c0 sqrt(N), i.e. N(t) = (sqrt(N_a) - c0 (t - t_a) / 2)^2 from the fit's first block
// on. Time in t0 of the run's series, so that runs of different droplets compare.
#include <algorithm>
#include <cmath>

#include "engine/protocol/drain_fit.h"
#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {

ReportFigure drain_curves(const FigureContext& c) {
  Figure f("drain_curves", "Draining hoppers: droplets left N(t) with the fit dN/dt = -c0 N^(1/2) (a few runs)",
           "t / t0", "N (droplets in the hopper)");
  if (!c.db.has_table("experiment_runs"))
    return finish(f, c.dir, "no imported draining-hopper runs (`beverloo experiment import`)");
  struct Pick {
    std::int64_t id;
    std::string label;
    double t0;
    int n0, skip, block;
  };
  std::vector<Pick> all;
  db::Statement runs = c.db.prepare(
      "SELECT r.id, s.name || ' ' || r.run || ' (w = ' || printf('%.2f', r.w) || ')', s.t0_s, r.n_initial, s.fit_skip, "
      "s.block_exits FROM experiment_runs r JOIN experiment_series s ON s.id = r.series_id WHERE r.Q IS NOT NULL "
      "ORDER BY s.id, r.w, r.run");
  while (runs.step())
    all.push_back({runs.get_int(0), runs.get_text(1), runs.get_double(2), static_cast<int>(runs.get_int(3)),
                   static_cast<int>(runs.get_int(4)), static_cast<int>(runs.get_int(5))});
  // at most six, spread over the list (so over series and widths)
  const std::size_t shown = std::min<std::size_t>(6, all.size());
  db::Statement exits = c.db.prepare("SELECT t_s FROM experiment_exits WHERE run_id = ?1 ORDER BY k");
  for (std::size_t i = 0; i < shown; ++i) {
    const Pick& p = all[shown > 1 ? i * (all.size() - 1) / (shown - 1) : 0];
    std::vector<double> t;
    exits.bind(1, p.id);
    while (exits.step()) t.push_back(exits.get_double(0));
    const DrainFit fit = fit_drain(t, p.n0, p.skip, p.block);
    const std::string style = series_style(static_cast<int>(i), static_cast<int>(shown));
    const int data = f.begin_block(p.label + ": t/t0 N (after each exit)");
    f.data << num(0) << " " << p.n0 << "\n";
    for (std::size_t k = 0; k < t.size(); ++k) f.data << num(t[k] / p.t0) << " " << (p.n0 - static_cast<int>(k) - 1) << "\n";
    f.plots.push_back("DATA index " + std::to_string(data) + " using 1:2 with steps " + style.substr(0, style.find(" pt")) +
                      " title " + gnuplot_string(p.label));
    if (!fit.ok) continue;
    // the law through the fit's first block: N_a droplets at t_a
    const int first = p.skip;
    const double t_a = t[first], n_a = p.n0 - first;
    const int curve = f.begin_block(p.label + ": fitted N(t) = (sqrt(N_a) - c0 (t - t_a)/2)^2");
    for (int s = 0; s <= 60; ++s) {
      const double tt = fit.t_first + (fit.t_last - fit.t_first) * s / 60.0;
      const double root = std::sqrt(n_a) - fit.c0 * (tt - t_a) / 2;
      if (root <= 0) break;
      f.data << num(tt / p.t0) << " " << num(root * root) << "\n";
    }
    f.plots.push_back("DATA index " + std::to_string(curve) + " using 1:2 with lines dt 2 lw 2 " +
                      style.substr(0, style.find(" pt")) + " notitle");
  }
  return finish(f, c.dir, "no imported draining-hopper run with a fit (`beverloo experiment import`)");
}

}  // namespace beverloo::figures
