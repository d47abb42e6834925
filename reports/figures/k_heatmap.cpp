// A heat map of the offset k over (K_l, K_b), one panel per DP group (model, E_c, lambda, N,
// wall angles); at most four panels (all fits are in the tables). A group in a dissipation
// limit (friction only or drag only) also gets the panel of k with beta held at d - 1/2 or
// d - 3/2, the way the paper fits k (series_fits.cpp): with four to seven widths per cell the
// free fit often cannot tell k from beta, and the paper's Fig. 7 is a map of the held form. A
// held k that lies above one of its fitted widths (the authors' |w - k| folds that width onto
// the law's mirror image) is ringed and its label says so, as k_vs_Esp rings it.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {

ReportFigure k_heatmap_Kl_Kb(const FigureContext& c) {
  Figure f("k_heatmap_Kl_Kb", "Offset k (in sigma_avg) over (K_l, K_b) (DP)", "K_l (epsilon_0)", "K_b (epsilon_0)");
  std::map<std::string, std::vector<const Series*>> by;
  for (const Series& s : c.fits.series)
    if (s.fit && s.is_dp() && !s.rate_is_c0())
      by[s.model + " E_c=" + num(s.E_c) + " lambda=" + format_lambda(s.lambda) + " N=" + std::to_string(s.N) +
         (s.theta_left != 90 || s.theta_right != 90 ? " theta=" + num(s.theta_left) + "/" + num(s.theta_right) : "")]
          .push_back(&s);
  // a panel: its title and its cells (K_l, K_b, the fit drawn)
  struct Panel {
    std::string title;
    std::vector<std::pair<const Series*, const BeverlooFit*>> cells;
  };
  std::vector<Panel> panels;
  double k_lo = INFINITY, k_hi = -INFINITY;
  auto add_panel = [&](Panel p) {
    std::set<std::pair<double, double>> grid;
    for (const auto& [s, fit] : p.cells) grid.insert({s->K_l, s->K_b});
    if (grid.size() < 2 || panels.size() == 4) return;
    for (const auto& [s, fit] : p.cells) k_lo = std::min(k_lo, fit->k), k_hi = std::max(k_hi, fit->k);
    panels.push_back(std::move(p));
  };
  for (auto& [label, list] : by) {
    Panel free_fit{label, {}};
    for (const Series* s : list) free_fit.cells.emplace_back(s, &*s->fit);
    add_panel(std::move(free_fit));
    const double lambda = list.front()->lambda;
    if (lambda != 0 && !std::isinf(lambda)) continue;
    const bool friction = lambda == 0;
    const int dimension = list.front()->dimension;
    // a short suffix: the panel's title must fit half the figure's width
    Panel held{label + ", beta = " + num(friction ? dimension - 0.5 : dimension - 1.5) + " held", {}};
    for (const Series* s : list)
      if (const auto& fit = friction ? s->authors_fixed_hi : s->authors_fixed_lo) held.cells.emplace_back(s, &*fit);
    add_panel(std::move(held));
  }
  if (!panels.empty()) {
    std::ostringstream body;
    body << "set logscale xy\nset offsets graph 0.15, graph 0.15, graph 0.15, graph 0.15\n"
         << "set palette defined (0 '#440154', 1 '#3B528B', 2 '#21908C', 3 '#5DC963', 4 '#FDE725')\n"  // viridis
         << "set cblabel 'k / sigma_avg' noenhanced\nset cbrange [" << num(k_lo) << ":" << num(k_hi > k_lo ? k_hi : k_lo + 1) << "]\n"
         << "set multiplot layout " << (panels.size() > 2 ? 2 : 1) << "," << (panels.size() > 2 ? 2 : panels.size()) << "\n";
    for (const Panel& p : panels) {
      const int block = f.begin_block(p.title + ": K_l K_b k k_err folded_widths");
      bool any_folded = false;
      for (const auto& [s, fit] : p.cells) {
        f.data << num(s->K_l) << " " << num(s->K_b) << " " << num(fit->k) << " " << num(fit->k_err) << " "
               << fit->folded_points << "\n";
        any_folded = any_folded || fit->folded_points > 0;
      }
      // each panel's group is its own title (the figure's title is the page's caption)
      body << "set title " << gnuplot_string(p.title) << " noenhanced font ',9'\n"
           << "plot DATA index " << block << " using 1:2:3 with points pt 5 ps 5 palette notitle, \\\n"
           << "     DATA index " << block
           << " using 1:2:(sprintf('%.2f+-%.2f%s', $3, $4, $5 > 0 ? ' (folds)' : '')) with labels offset 0,2 font ',8' notitle";
      if (any_folded)
        body << ", \\\n     DATA index " << block
             << " using 1:($5 > 0 ? $2 : 1/0) with points pt 6 ps 6 lw 2 lc rgb '#000000' "
                "title 'held k above a fitted width (|w - k| folds it)'";
      body << "\n";
    }
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir, "needs fitted DP series at two or more (K_l, K_b) with the other parameters equal");
}

}  // namespace beverloo::figures
