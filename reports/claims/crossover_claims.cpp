// beta(lambda)'s crossover: lambda_c and 1/b with each sigmoid, and lambda_c's fall with the
// hopper angle (Fig. 4, 6).
#include "reports/claims/checks.h"
#include "reports/claims/verdict.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "reports/crossover_groups.h"
#include "reports/number_format.h"
#include "reports/series_fits.h"

namespace beverloo::claims {

namespace {
/// lambda_c as the paper states it (2D: ~0.05 at theta_w = 90, ~6e-3 at 20; 3D: ~0.07 at 90).
bool paper_lambda_c(const Crossover& g, double& value, std::string& text) {
  if (g.finite.empty()) return false;
  const Series& s = *g.finite.front();
  if (s.theta_left != s.theta_right) return false;
  if (g.dimension == 2 && s.theta_left == 90) value = 0.05, text = "~0.05 (2D, theta_w = 90)";
  else if (g.dimension == 2 && s.theta_left == 20) value = 6e-3, text = "~6e-3 (2D, theta_w = 20)";
  else if (g.dimension == 3 && s.theta_left == 90) value = 0.07, text = "~0.07 (3D, theta_w = 90)";
  else return false;
  return true;
}

/// ", spread 0.12 in log10 over 3 replicas", or "" without replicas.
std::string lambda_c_spread_text(const Crossover::ReplicaSpread& spread) {
  const std::string phrase = lambda_c_spread_phrase(spread);
  return phrase.empty() ? phrase : ", " + phrase;
}

/// The spread of log10 lambda_c, or "none" (fewer than two replicas with every width of the fit).
std::string spread_or_none(const Crossover::ReplicaSpread& spread) {
  return std::isnan(spread.log10_lambda_c) ? "none" : format_value(spread.log10_lambda_c, 2);
}

/// The smallest and largest finite lambda of a group's fitted series.
std::pair<double, double> measured_lambdas(const Crossover& g) {
  double lo = INFINITY, hi = 0;
  for (const Series* s : g.finite) lo = std::min(lo, s->lambda), hi = std::max(hi, s->lambda);
  return {lo, hi};
}

/// Whether a fit's lambda_c lies among its group's measured lambdas (else the sigmoid's
/// extrapolation: with the paper's fixed plateaus it goes there when the data never cross d - 1).
bool inside_measured(const CrossoverFit& fit, const Crossover& g) {
  const auto [lo, hi] = measured_lambdas(g);
  return fit.lambda_c >= lo && fit.lambda_c <= hi;
}

/// lambda_c against the paper's value on the scale it is fitted and drawn on (log10 lambda_c,
/// with its own error): a linear z would call a lambda_c of 15 +- 8 "2 sigma from 0.07". A
/// midpoint outside the group's measured lambdas is an extrapolation of the sigmoid (with the
/// paper's fixed plateaus it goes there when the data never cross d - 1, e.g. 3D flows whose
/// exponents all lie above 2): no verdict. `spread`: the replicas' spread of this fit.
void judge_lambda_c(ClaimCheck& c, const CrossoverFit& fit, const Crossover& g, const Crossover::ReplicaSpread& spread,
                    double paper_value) {
  const double log10_sigma = log10_lambda_c_sigma(fit, spread);
  const auto [lo, hi] = measured_lambdas(g);
  if (!inside_measured(fit, g)) {
    c.verdict = "not judged: lambda_c outside the measured lambdas (" + format_value(lo, 2) + " .. " + format_value(hi, 2) +
                "), an extrapolation (chi2_red " + format_value(fit.chi2_red, 2) + ")";
    return;
  }
  if (!(log10_sigma > 0)) {
    c.verdict = "not judged: no error";
    return;
  }
  const double z = std::fabs(fit.log10_lambda_c - std::log10(paper_value)) / log10_sigma;
  c.judged = true;
  c.agrees = z <= kClaimAgreeSigmas;
  c.verdict = std::string(c.agrees ? "agrees" : "differs") + " (z = " + z_text(z) + " in log10 lambda_c)";
  append_chi2_scaled_z(c, (fit.log10_lambda_c - std::log10(paper_value)) / log10_lambda_c_sigma_chi2_scaled(fit, spread),
                       {chi2_scale(fit)});
}

/// Eq. 2's 0 < 1/b < 1 with one crossover fit: consistent when 1/b lies within
/// kClaimAgreeSigmas sigma of the interval. Both fits are checked, each named: the paper's
/// fixed plateaus force the curve from d - 1/2 to d - 3/2, and where the points' own limits lie
/// elsewhere its b belongs to a curve that misses them (the text set's Fig. 4a: 1/b = 0.21 at
/// chi2_red 29, with free plateaus 1.16 at 1.65), so its verdict alone would judge the form,
/// not the data.
ClaimCheck stretching_check(const Crossover& g, const CrossoverFit& fit, bool plateaus_free,
                            const Crossover::ReplicaSpread& spread) {
  ClaimCheck c;
  c.claim = std::string("stretching exponent of beta(lambda): 0 < 1/b < 1 (Eq. 2), ") +
            (plateaus_free ? "the sigmoid with free plateaus" : "the paper's sigmoid (plateaus d - 1/2, d - 3/2)");
  c.subject = g.label;
  c.paper = "0 < 1/b < 1";
  c.measured = 1 / fit.b;
  // sigma: the larger of b's fit error and its spread over the replicas' own fits
  const double b_sigma = std::isnan(spread.b) ? fit.b_err : std::max(fit.b_err, spread.b);
  c.sigma = b_sigma / (fit.b * fit.b);
  c.measured_text = format_with_error(c.measured, c.sigma, " +- ") + " (chi2_red " + format_value(fit.chi2_red, 2);
  if (!std::isnan(spread.b))
    c.measured_text += "; b's spread " + format_value(spread.b, 2) + " over " + std::to_string(spread.replicas) + " replicas";
  c.measured_text += ")";
  const double nearest = c.measured < 0 ? 0 : c.measured > 1 ? 1 : c.measured;
  if (!(c.sigma > 0)) {
    c.verdict = "not judged: no error";
    return c;
  }
  const double z = std::fabs(c.measured - nearest) / c.sigma;
  c.judged = true;
  c.agrees = z <= kClaimAgreeSigmas;
  c.verdict = std::string(c.agrees ? "agrees" : "differs") + " (z = " + z_text(z) + " from the interval)";
  if (nearest == c.measured) return c;  // inside the interval: no scale changes that
  // b's fit error scaled by sqrt(chi2_red), the replicas' spread as it is (as for lambda_c)
  const double scaled_b_sigma = std::isnan(spread.b) ? fit.b_err * chi2_scale(fit)
                                                     : std::max(fit.b_err * chi2_scale(fit), spread.b);
  append_chi2_scaled_z(c, (c.measured - nearest) / (scaled_b_sigma / (fit.b * fit.b)), {chi2_scale(fit)});
  return c;
}

/// "0.0032 (between 0.001 and 0.0036)": a crossing of d - 1 and the measured lambdas around it.
std::string crossing_text(const MidpointCrossing& m) {
  return format_value(std::pow(10.0, m.log10_lambda), 2) + " (between " + format_value(m.lambda_lo, 2) + " and " +
         format_value(m.lambda_hi, 2) + ")";
}

/// A crossing's replica spread in log10, "0.042 over 3 replicas", or "none".
std::string crossing_spread_text(const MidpointCrossing& m) {
  return std::isnan(m.spread) ? std::string("none")
                              : format_value(m.spread, 2) + " over " + std::to_string(m.replicas) + " replicas";
}

/// A crossing's interpolation error in log10, or "none (no neighbouring lambda)".
std::string crossing_interpolation_text(const MidpointCrossing& m) {
  return std::isnan(m.interpolation) ? std::string("none (no neighbouring lambda)") : format_value(m.interpolation, 2);
}

/// "; beta turns back next to the crossing (z = 9.5): ..." where a neighbouring step goes
/// against the bracketing pair's direction by more than kClaimAgreeSigmas, else "".
std::string reversal_text(const MidpointCrossing& m, const std::string& where = "") {
  if (!(m.reversal_z > kClaimAgreeSigmas)) return "";
  return "; beta turns back next to the crossing" + where + " (z = " + z_text(m.reversal_z) +
         "): not monotone there, the chord rests on that stretch";
}

/// lambda_c without a sigmoid: where the measured beta(lambda) crosses d - 1, the paper's
/// midpoint by construction, against the paper's value in log10, sigma MidpointCrossing's
/// verdict_sigma. The paper's own exponents were rescaled before its fit (docs/paper.md,
/// "Facts"); these are not, and the row says so.
ClaimCheck crossing_lambda_c_check(const Crossover& g, const MidpointCrossing& m, double paper_value,
                                   const std::string& paper_text) {
  ClaimCheck c;
  c.claim = "lambda_c of beta(lambda) (Fig. 4, 6), where beverloo's exponents (not rescaled) cross d - 1, interpolated: "
            "no sigmoid";
  c.subject = g.label;
  c.paper = paper_text;
  c.measured = std::pow(10.0, m.log10_lambda);
  const double log10_sigma = m.verdict_sigma();
  c.sigma = c.measured * std::log(10.0) * log10_sigma;
  c.measured_text = crossing_text(m) + "; sigma of log10 " + format_value(log10_sigma, 2) + ": the exponents' errors " +
                    format_value(m.sigma, 2) + ", the replicas' spread " + crossing_spread_text(m) +
                    ", the interpolation's " + crossing_interpolation_text(m) + reversal_text(m);
  if (!(log10_sigma > 0)) {
    c.verdict = "not judged: no error";
    return c;
  }
  const double z = std::fabs(m.log10_lambda - std::log10(paper_value)) / log10_sigma;
  c.judged = true;
  c.agrees = z <= kClaimAgreeSigmas;
  c.verdict = std::string(c.agrees ? "agrees" : "differs") + " (z = " + z_text(z) + " in log10 lambda)";
  return c;
}

}  // namespace

void crossover_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out) {
  for (const Crossover& g : fits.crossovers) {
    double value = 0;
    std::string text;
    const bool stated = paper_lambda_c(g, value, text);
    for (const auto* f : {&g.fit, &g.fit_free}) {
      if (!*f || !stated) continue;
      ClaimCheck c;
      c.claim = std::string("lambda_c of beta(lambda) (Fig. 4, 6), ") +
                (f == &g.fit ? "the paper's sigmoid (plateaus d - 1/2, d - 3/2)" : "the sigmoid with free plateaus");
      c.subject = g.label;
      c.paper = text;
      c.measured = (*f)->lambda_c;
      const Crossover::ReplicaSpread& spread = f == &g.fit ? g.spread : g.spread_free;
      c.measured_text = format_with_error((*f)->lambda_c, (*f)->lambda_c_err, " +- ") + lambda_c_spread_text(spread);
      const double log10_sigma = log10_lambda_c_sigma(**f, spread);
      c.sigma = (*f)->lambda_c * std::log(10.0) * log10_sigma;  // the verdict's sigma, on the linear scale
      judge_lambda_c(c, **f, g, spread, value);
      out.push_back(c);
    }
    if (stated)
      if (const std::optional<MidpointCrossing> m = crossing_of_d_minus_1(g)) out.push_back(crossing_lambda_c_check(g, *m, value, text));
    for (const auto* f : {&g.fit, &g.fit_free})
      if (*f && (*f)->b > 0) out.push_back(stretching_check(g, **f, f == &g.fit_free, f == &g.fit ? g.spread : g.spread_free));
  }
}

/// Fig. 6: lambda_c falls as theta_w falls ("from 5e-2 at 90 deg to 6e-3 at 20"), checked as
/// lambda_c(theta_w) / lambda_c(90) of the groups that differ only in the hopper angle
/// (Crossover::angle_family), with each crossover fit. The claim is a direction, so the verdict
/// is one: a fall when the ratio lies below 1 by more than kClaimAgreeSigmas sigma (sigma of
/// log10 of the ratio, from both lambda_c), a rise when above it by as much, and neither is
/// claimed when the ratio is within that of 1. Below 30 deg the paper has a plateau ("~5e-3 for
/// theta_w <= 30"), checked as lambda_c(theta_w) / lambda_c(30): it agrees within
/// kClaimAgreeSigmas sigma of 1 and differs, falling or rising, beyond.
void theta_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out) {
  auto paper_text = [](double theta, bool plateau) -> std::string {
    return plateau ? "~1 (a plateau)" : theta == 20 ? "~0.12 (6e-3 / 5e-2)" : "< 1 (5e-2 at 90 deg, 6e-3 at 20)";
  };
  // the ratio's verdict in log10: a plateau is no change, else the claimed fall
  auto judge_ratio = [](ClaimCheck& c, double log_ratio, double log_sigma, bool plateau) {
    if (!(log_sigma > 0))
      c.verdict = "not judged: no error";
    else if (plateau)
      judge_no_change(c, log_ratio / log_sigma);
    else
      judge_direction(c, -log_ratio / log_sigma, "falls", "rises");
  };
  for (const auto& [family, by_theta] : angle_families(fits.crossovers, /*fitted_only=*/false)) {
    auto compare = [&](double theta, const Crossover& g, double reference, bool plateau) {
      const auto ref = by_theta.find(reference);
      if (ref == by_theta.end()) return;
      for (const bool free : {false, true}) {
        const std::optional<CrossoverFit>& at = free ? g.fit_free : g.fit;
        const std::optional<CrossoverFit>& at_ref = free ? ref->second->fit_free : ref->second->fit;
        if (!at || !at_ref || !(at->lambda_c > 0) || !(at_ref->lambda_c > 0)) continue;
        const Crossover::ReplicaSpread &spread = free ? g.spread_free : g.spread,
                                       &spread_ref = free ? ref->second->spread_free : ref->second->spread;
        ClaimCheck c;
        const std::string fit_name = free ? "the sigmoid with free plateaus" : "the paper's sigmoid";
        const std::string ref_text = format_value(reference, 3);
        c.claim = plateau ? "lambda_c stops falling below theta_w = 30 deg (Fig. 6, a plateau ~5e-3), " + fit_name +
                                ": lambda_c(theta_w) / lambda_c(30)"
                          : "lambda_c falls as theta_w falls (Fig. 6), " + fit_name + ": lambda_c(theta_w) / lambda_c(90)";
        c.subject = g.label + " at theta_w = " + format_value(theta, 3);
        c.paper = paper_text(theta, plateau);
        const double log_ratio = at->log10_lambda_c - at_ref->log10_lambda_c;
        const double log_sigma =
            std::hypot(log10_lambda_c_sigma(*at, spread), log10_lambda_c_sigma(*at_ref, spread_ref));
        c.measured = std::pow(10.0, log_ratio);
        c.sigma = c.measured * std::log(10.0) * log_sigma;
        c.measured_text = format_with_error(c.measured, c.sigma, " +- ") + " (" +
                          format_with_error(at->lambda_c, at->lambda_c_err, " +- ") + " against " +
                          format_with_error(at_ref->lambda_c, at_ref->lambda_c_err, " +- ") +
                          (plateau ? " at 30 deg" : "") + ")";
        if (!std::isnan(spread.log10_lambda_c) || !std::isnan(spread_ref.log10_lambda_c))
          c.measured_text += "; spread of log10 lambda_c over replicas " + spread_or_none(spread) + " and " +
                             spread_or_none(spread_ref) + " at " + ref_text + " deg";
        const std::string outside = !inside_measured(*at, g)                 ? format_value(theta, 3)
                                    : !inside_measured(*at_ref, *ref->second) ? ref_text
                                                                              : "";
        if (!outside.empty()) {
          // a midpoint beyond a group's measured lambdas is the sigmoid's extrapolation
          c.verdict = "not judged: lambda_c at " + outside + " deg outside its measured lambdas, an extrapolation";
          out.push_back(c);
          continue;
        }
        judge_ratio(c, log_ratio, log_sigma, plateau);
        const double log_sigma_scaled = std::hypot(log10_lambda_c_sigma_chi2_scaled(*at, spread),
                                                   log10_lambda_c_sigma_chi2_scaled(*at_ref, spread_ref));
        append_chi2_scaled_z(c, log_ratio / log_sigma_scaled, {chi2_scale(*at), chi2_scale(*at_ref)});
        out.push_back(c);
      }
      // the same without a sigmoid: where each group's measured beta crosses d - 1
      const std::optional<MidpointCrossing> at = crossing_of_d_minus_1(g), at_ref = crossing_of_d_minus_1(*ref->second);
      if (!at || !at_ref) return;
      ClaimCheck c;
      c.claim = plateau ? "lambda_c stops falling below theta_w = 30 deg (Fig. 6, a plateau ~5e-3), where beta crosses d - 1 "
                          "(interpolated): lambda(theta_w) / lambda(30)"
                        : "lambda_c falls as theta_w falls (Fig. 6), where beta crosses d - 1 (interpolated): lambda(theta_w) / "
                          "lambda(90)";
      c.subject = g.label + " at theta_w = " + format_value(theta, 3);
      c.paper = paper_text(theta, plateau);
      const double log_ratio = at->log10_lambda - at_ref->log10_lambda,
                   log_sigma = std::hypot(at->verdict_sigma(), at_ref->verdict_sigma());
      c.measured = std::pow(10.0, log_ratio);
      c.sigma = c.measured * std::log(10.0) * log_sigma;
      c.measured_text = format_with_error(c.measured, c.sigma, " +- ") + " (" + crossing_text(*at) + " against " +
                        crossing_text(*at_ref) + " at " + format_value(reference, 3) + " deg";
      if (!std::isnan(at->spread) || !std::isnan(at_ref->spread))
        c.measured_text += "; spread of log10 lambda " + crossing_spread_text(*at) + " and " + crossing_spread_text(*at_ref) +
                           " at " + format_value(reference, 3) + " deg";
      c.measured_text += "; sigma from the exponents' errors or the replicas' spread, and in quadrature the "
                         "interpolation's, where a parabola through a neighbouring lambda moves the crossing: " +
                         crossing_interpolation_text(*at) + " and " + crossing_interpolation_text(*at_ref) + " decades" +
                         reversal_text(*at, " at " + format_value(theta, 3) + " deg") +
                         reversal_text(*at_ref, " at " + format_value(reference, 3) + " deg") + ")";
      judge_ratio(c, log_ratio, log_sigma, plateau);
      out.push_back(c);
    };
    for (const auto& [theta, g] : by_theta)
      if (theta < 90) compare(theta, *g, 90, false);
    for (const auto& [theta, g] : by_theta)
      if (theta < 30) compare(theta, *g, 30, true);
  }
}

}  // namespace beverloo::claims
