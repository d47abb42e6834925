// The paper's Fig. C(b): the prefactor C of Q = C (w - k)^beta against the number of particles
// N, normalized by its value at the smallest N, in the two dissipation limits, for series that
// differ only in N. C is read from the fit with beta held at d - 1/2 (friction only) or d - 3/2
// (drag only), solid: C carries the units of sigma_avg^(d - 1/2 - beta) / t0, so Cs fitted with
// different free exponents are not on one scale, and the free exponent moves with N here
// (docs/paper.md, Appendix C). The free fit's C is drawn dashed beside it.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {
namespace {

/// C / C(smallest N) with its error (the two relative errors in quadrature: independent runs).
struct NormalizedC {
  double N, ratio, err;
};

template <class FitOf>
std::vector<NormalizedC> normalized(const std::vector<const Series*>& by_N, FitOf fit_of) {
  std::vector<NormalizedC> out;
  const BeverlooFit* first = nullptr;
  for (const Series* s : by_N) {
    const BeverlooFit* f = fit_of(*s);
    if (!f || !(f->C > 0)) continue;
    if (!first) first = f;
    const double ratio = f->C / first->C;
    const double rel = f == first ? 0.0 : std::hypot(f->C_err / f->C, first->C_err / first->C);
    out.push_back({static_cast<double>(s->N), ratio, ratio * rel});
  }
  return out;
}

}  // namespace

ReportFigure prefactor_vs_N(const FigureContext& c) {
  Figure f("C_vs_N", "Prefactor C versus N, normalized by the smallest N (Fig. C(b))", "N",
           "C(N) / C(smallest N)");
  // series in a limit, grouped by all but N
  std::map<std::string, std::vector<const Series*>> groups;
  for (const Series& s : c.fits.series) {
    if (s.rate_is_c0() || s.model == "experiment" || !(s.lambda == 0 || std::isinf(s.lambda))) continue;
    groups[s.size_free_key].push_back(&s);
  }
  std::vector<std::vector<const Series*>> lines;
  for (auto& [key, list] : groups) {
    std::set<int> sizes;
    for (const Series* s : list) sizes.insert(s->N);
    if (sizes.size() < 2) continue;  // (one series per N: the key holds all else)
    std::sort(list.begin(), list.end(), [](const Series* a, const Series* b) { return a->N < b->N; });
    lines.push_back(list);
  }
  int k = 0;
  for (const auto& list : lines) {
    const Series& first = *list.front();
    const bool friction = first.lambda == 0;
    const std::string style = series_style(k++, static_cast<int>(lines.size()));
    std::string label = std::to_string(first.dimension) + "D " + first.stiffness + (friction ? ", friction only" : ", drag only");
    if (first.theta_left != 90 || first.theta_right != 90) label += " theta=" + num(first.theta_left) + "/" + num(first.theta_right);
    const std::string beta = num(friction ? first.dimension - 0.5 : first.dimension - 1.5);
    const auto held = normalized(list, [friction](const Series& s) -> const BeverlooFit* {
      const std::optional<BeverlooFit>& h = friction ? s.authors_fixed_hi : s.authors_fixed_lo;
      return h ? &*h : nullptr;
    });
    if (held.size() >= 2) {
      const int block = f.begin_block(label + ": N C/C(N_min) err, beta held at " + beta);
      for (const NormalizedC& p : held) f.data << num(p.N) << " " << num(p.ratio) << " " << num(p.err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2:3 with yerrorlines " + style + " title " +
                        gnuplot_string(label + ", beta held at " + beta));
    }
    const auto free = normalized(list, [](const Series& s) -> const BeverlooFit* { return s.fit ? &*s.fit : nullptr; });
    if (free.size() >= 2) {
      const int block = f.begin_block(label + ": N C/C(N_min) err, free fit");
      for (const NormalizedC& p : free) f.data << num(p.N) << " " << num(p.ratio) << " " << num(p.err) << "\n";
      f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2:3 with yerrorlines dt 2 " +
                        style.substr(0, style.find(" pt")) + " title " + gnuplot_string(label + ", free fit"));
    }
  }
  return finish(f, c.dir, "needs fitted series in a dissipation limit at two or more N with the other parameters equal");
}

}  // namespace beverloo::figures
