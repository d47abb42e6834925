// The offset k versus the paper's softness axes, per dissipation setting: E_sp for SP, K_b
// for DP (DP groups also keep K_l and E_c fixed). In the two limits also, dashed, k of the fit
// with beta held at d - 1/2 (lambda = 0) or d - 3/2 (lambda = inf), the way the paper fits
// (series_fits.cpp): the free fit trades k against beta, the paper's fit puts it all in k. A
// held k that lies above one of its fitted widths (the authors' |w - k| folds that width) is
// ringed: such a k describes the width range more than the orifice (docs/paper.md, Fig. 7a).
// The frame, as beta_vs_lambda's, is widened only by k measured to kFrameKErr or better: a k of
// -3.6 +- 6.5 (a series of the text set's Fig. 4a whose free fit cannot tell k from beta)
// squeezed every other k into a fifth of the frame. Such a k is left beyond it and counted.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/text_escape.h"
#include "figure.h"
#include "reports/number_format.h"

namespace beverloo::figures {
namespace {

constexpr double kFrameKErr = 1.0, kFrameMargin = 0.3;  // sigma_avg

/// The plotted k: [lo, hi] spans k +- k_err of those with k_err <= kFrameKErr.
struct KFrame {
  double lo = INFINITY, hi = -INFINITY;
  int left_out = 0;
  std::vector<double> ks;
  void add(double k, double k_err) {
    if (!std::isfinite(k)) return;
    ks.push_back(k);
    if (std::isfinite(k_err) && k_err <= kFrameKErr)
      lo = std::min(lo, k - k_err), hi = std::max(hi, k + k_err);
    else
      ++left_out;
  }
};

ReportFigure k_versus(const FigureContext& c, bool dp) {
  Figure f(dp ? "k_vs_Kb" : "k_vs_Esp", dp ? "Offset k versus bending stiffness K_b (DP)" : "Offset k versus stiffness E_sp (SP)",
           dp ? "K_b (epsilon_0)" : "E_sp (g rho sigma_avg^(d+1))", "k / sigma_avg", "set logscale x\n");
  auto stiffness = [dp](const Series* s) { return dp ? s->K_b : s->E_sp; };
  std::map<std::string, std::vector<const Series*>> by;
  for (const Series& s : c.fits.series) {
    if (!s.fit || s.is_dp() != dp || s.rate_is_c0() || s.model == "experiment") continue;
    std::string label = std::to_string(s.dimension) + "D ";
    if (dp) label += s.model + " K_l=" + num(s.K_l) + " E_c=" + num(s.E_c) + " ";
    by[label + "lambda=" + format_lambda(s.lambda) + " N=" + std::to_string(s.N)].push_back(&s);
  }
  std::vector<std::pair<std::string, std::vector<const Series*>>> lines;
  for (auto& [label, list] : by) {
    std::set<double> values;
    for (const Series* s : list) values.insert(stiffness(s));
    if (values.size() < 2) continue;
    std::sort(list.begin(), list.end(), [&](const Series* a, const Series* b) { return stiffness(a) < stiffness(b); });
    lines.emplace_back(label, list);
  }
  std::vector<std::pair<double, double>> folded;  // (stiffness, held k) of fits that fold a width
  KFrame frame;
  int k = 0;
  for (const auto& [label, list] : lines) {
    const std::string style = series_style(k++, static_cast<int>(lines.size()));
    const int block = f.begin_block(label + (dp ? ": K_b k k_err" : ": E_sp k k_err"));
    for (const Series* s : list) {
      f.data << num(stiffness(s)) << " " << num(s->fit->k) << " " << num(s->fit->k_err) << "\n";
      frame.add(s->fit->k, s->fit->k_err);
    }
    f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2:3 with yerrorlines " + style + " title " +
                      gnuplot_string(label));
    // the limits: k with beta held as the paper fits
    const double lambda = list.front()->lambda;
    if (lambda != 0 && !std::isinf(lambda)) continue;
    const bool friction = lambda == 0;
    std::vector<const Series*> fixed;
    for (const Series* s : list)
      if (friction ? s->authors_fixed_hi.has_value() : s->authors_fixed_lo.has_value()) fixed.push_back(s);
    if (fixed.size() < 2) continue;
    const int held = f.begin_block(label + (dp ? ": K_b" : ": E_sp") + " k k_err with beta held (the paper's way)");
    for (const Series* s : fixed) {
      const BeverlooFit& fit = friction ? *s->authors_fixed_hi : *s->authors_fixed_lo;
      f.data << num(stiffness(s)) << " " << num(fit.k) << " " << num(fit.k_err) << "\n";
      frame.add(fit.k, fit.k_err);
      if (fit.folded_points > 0) folded.emplace_back(stiffness(s), fit.k);
    }
    const std::string beta = friction ? num(list.front()->dimension - 0.5) : num(list.front()->dimension - 1.5);
    f.plots.push_back("DATA index " + std::to_string(held) + " using 1:2:3 with yerrorlines dt 2 " +
                      style.substr(0, style.find(" pt")) + " title " + gnuplot_string(label + ", beta held at " + beta));
  }
  // a frame only where a k is left out (otherwise gnuplot's own range holds every point)
  if (frame.left_out > 0 && frame.lo <= frame.hi) {
    // the beyond count: k outside the frame (a poorly known k can still lie inside it)
    int beyond = 0;
    for (const double k_value : frame.ks) beyond += k_value < frame.lo - kFrameMargin || k_value > frame.hi + kFrameMargin;
    f.extra += "set yrange [" + num(frame.lo - kFrameMargin) + ":" + num(frame.hi + kFrameMargin) + "]\n";
    if (beyond > 0)
      f.extra += "set label " +
                 gnuplot_string(std::to_string(beyond) + (beyond == 1 ? " k" : " ks") + " with an error above " +
                                format_value(kFrameKErr, 2) + " beyond the frame (beverloo_fits.md)") +
                 " at graph 0.02, graph 0.04 font ',9' noenhanced\n";
  }
  if (!folded.empty()) {
    const int ring = f.begin_block(std::string(dp ? "K_b" : "E_sp") + " k of held fits whose k lies above a fitted width");
    for (const auto& [x, held_k] : folded) f.data << num(x) << " " << num(held_k) << "\n";
    f.plots.push_back("DATA index " + std::to_string(ring) +
                      " using 1:2 with points pt 6 ps 2.5 lc rgb '#000000' title 'held k above a fitted width (|w - k| folds it)'");
  }
  return finish(f, c.dir,
                dp ? "needs fitted DP series at two or more K_b with the other parameters equal"
                   : "needs fitted SP series at two or more E_sp with the other parameters equal");
}

}  // namespace

ReportFigure k_vs_Esp(const FigureContext& c) { return k_versus(c, false); }
ReportFigure k_vs_Kb(const FigureContext& c) { return k_versus(c, true); }

}  // namespace beverloo::figures
