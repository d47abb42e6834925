// Appendix B's corrected flow rate Q' = Q a_eff / a_avg versus w per continuous-flow series
// (a_eff = 1/rho_n near the orifice: the area that left counted with the packing's own particle
// area), each with its own fit Q' = C' (w - k')^beta' and a legend giving beta beside beta': for
// soft particles the paper's Fig. B moves the exponent, for small overlaps beta' = beta.
#include <map>

#include "figure.h"

namespace beverloo::figures {

ReportFigure q_prime_vs_w(const FigureContext& c) {
  Figure f("Q_prime_vs_w", "Corrected flow rate Q' = Q a_eff / a_avg (paper Appendix B), fits Q' = C' (w - k')^beta'",
           "w / sigma_avg", "Q' / Q_0");
  std::map<std::string, const Series*> of_q;
  for (const Series& s : c.fits.series) of_q[s.key] = &s;
  const CampaignFits prime = fit_campaign(c.db, FlowRate::QPrime, c.scope);
  std::vector<Series> shown;
  for (const Series& s : prime.series) {
    if (s.rate_is_c0()) continue;
    Series t = s;
    const auto q = of_q.find(s.key);
    const std::string beta = q != of_q.end() && q->second->fit ? table_number(q->second->fit->beta, 3) : "-";
    t.label += " (beta " + beta + ", beta' " + (s.fit ? table_number(s.fit->beta, 3) : std::string("-")) + ")";
    shown.push_back(std::move(t));
  }
  std::vector<const Series*> list;
  for (const Series& s : shown) list.push_back(&s);
  plot_q_vs_w(f, list);
  return finish(f, c.dir, "no finished jobs");
}

}  // namespace beverloo::figures
