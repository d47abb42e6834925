// A heat map of the offset k over (K_l, K_b), one panel per DP group (model, E_c, lambda, N,
// wall angles); at most four panels (all fits are in the tables).
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
  std::vector<std::pair<std::string, std::vector<const Series*>>> panels;
  double k_lo = INFINITY, k_hi = -INFINITY;
  for (auto& [label, list] : by) {
    std::set<std::pair<double, double>> grid;
    for (const Series* s : list) grid.insert({s->K_l, s->K_b});
    if (grid.size() < 2 || panels.size() == 4) continue;
    for (const Series* s : list) k_lo = std::min(k_lo, s->fit->k), k_hi = std::max(k_hi, s->fit->k);
    panels.emplace_back(label, list);
  }
  if (!panels.empty()) {
    std::ostringstream body;
    body << "set logscale xy\nset offsets graph 0.15, graph 0.15, graph 0.15, graph 0.15\n"
         << "set palette defined (0 '#440154', 1 '#3B528B', 2 '#21908C', 3 '#5DC963', 4 '#FDE725')\n"  // viridis
         << "set cblabel 'k / sigma_avg'\nset cbrange [" << num(k_lo) << ":" << num(k_hi > k_lo ? k_hi : k_lo + 1) << "]\n"
         << "set multiplot layout 1," << panels.size() << "\n";
    for (const auto& [label, list] : panels) {
      const int block = f.begin_block(label + ": K_l K_b k k_err");
      for (const Series* s : list)
        f.data << num(s->K_l) << " " << num(s->K_b) << " " << num(s->fit->k) << " " << num(s->fit->k_err) << "\n";
      // each panel's group is its own title (the figure's title is the page's caption)
      body << "set title " << gnuplot_string(label) << " noenhanced font ',9'\n"
           << "plot DATA index " << block << " using 1:2:3 with points pt 5 ps 5 palette notitle, \\\n"
           << "     DATA index " << block
           << " using 1:2:(sprintf('%.2f+-%.2f', $3, $4)) with labels offset 0,2 font ',8' notitle\n";
    }
    body << "unset multiplot";
    f.body = body.str();
  }
  return finish(f, c.dir, "needs fitted DP series at two or more (K_l, K_b) with the other parameters equal");
}

}  // namespace beverloo::figures
