#include "reports/claims/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reports/fit.h"
#include "reports/number_format.h"
#include "reports/series_fits.h"

namespace beverloo::claims {

bool at_right_angle(const Series& s) { return s.theta_left == 90 && s.theta_right == 90; }

/// A simulated flow at theta_w = 90 (the paper's exponents and C are stated for that hopper).
bool simulated_flow(const Series& s) { return !s.rate_is_c0() && at_right_angle(s); }

std::string z_text(double z) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", z);
  return buf;
}

/// The verdict of measured against the paper's value with the measurement's sigma.
void judge(ClaimCheck& c, double paper_value) {
  if (!(c.sigma > 0) || !std::isfinite(c.measured)) {
    c.verdict = "not judged: no error";
    return;
  }
  const double z = std::fabs(c.measured - paper_value) / c.sigma;
  c.judged = true;
  c.agrees = z <= kClaimAgreeSigmas;
  c.verdict = std::string(c.agrees ? "agrees" : "differs") + " (z = " + z_text(z) + ")";
}

/// The verdict on a claimed direction: z, the measured change in sigma, positive in the claimed
/// direction (`claimed`, e.g. "falls"; `opposite` the other way). Beyond kClaimAgreeSigmas either
/// way it is judged; within it, "not resolved".
void judge_direction(ClaimCheck& c, double z, const char* claimed, const char* opposite) {
  c.judged = std::fabs(z) > kClaimAgreeSigmas;
  c.agrees = z > kClaimAgreeSigmas;
  c.verdict = c.judged ? std::string(c.agrees ? "agrees (" : "differs (") + (c.agrees ? claimed : opposite) + ", z = " +
                             z_text(std::fabs(z)) + ")"
                       : "not resolved (within " + z_text(std::fabs(z)) + " sigma of no change)";
}

/// The verdict on a claimed absence of change (a plateau): z, the measured change in sigma,
/// positive for a rise. Within kClaimAgreeSigmas it agrees; beyond, it differs and says which way.
void judge_no_change(ClaimCheck& c, double z) {
  c.judged = true;
  c.agrees = std::fabs(z) <= kClaimAgreeSigmas;
  c.verdict = c.agrees ? "agrees (z = " + z_text(std::fabs(z)) + ")"
                       : std::string(z > 0 ? "differs (rises" : "differs (falls") + ", z = " + z_text(std::fabs(z)) + ")";
}

/// Appended to a judged verdict on lambda_c or an exponent where a fit's chi2_red exceeds 1: the
/// z of the same comparison with each fit's error scaled by sqrt(chi2_red) (chi2_scale,
/// beverloo_chi2_scale), and those factors. The verdict keeps the page's rule (docs/paper.md);
/// this says how much of it rests on a curve that does not pass through its points within
/// their errors.
void append_chi2_scaled_z(ClaimCheck& c, double z_scaled, const std::vector<double>& scales) {
  if (!c.judged || !std::isfinite(z_scaled)) return;
  std::string factors;
  bool scaled = false;
  for (const double s : scales) {
    scaled = scaled || s > 1;
    factors += (factors.empty() ? "" : ", ") + format_value(s, 2);
  }
  if (!scaled) return;
  c.verdict += "; z = " + z_text(std::fabs(z_scaled)) + " with " + (scales.size() > 1 ? "the fits' errors" : "the fit's error") +
               " scaled by sqrt(chi2_red) (" + factors + ")";
}

/// The sigma of a series' exponent for a verdict: the larger of the fit error and the spread
/// over replicas (the fit error alone without replicas).
double beta_sigma(const Series& s) {
  return std::isnan(s.beta_replica_spread) ? s.fit->beta_err : std::max(s.fit->beta_err, s.beta_replica_spread);
}

/// chi2_error_scale (fit.h) of a series' Beverloo fit.
double beverloo_chi2_scale(const Series& s) { return chi2_error_scale(s.fit->chi2_red); }

/// beta_sigma with the fit's error scaled by beverloo_chi2_scale (the spread over replicas as it is).
double beta_sigma_chi2_scaled(const Series& s) {
  const double scaled = s.fit->beta_err * beverloo_chi2_scale(s);
  return std::isnan(s.beta_replica_spread) ? scaled : std::max(scaled, s.beta_replica_spread);
}

/// An exponent of a series: its fit's beta with beta_sigma.
ClaimCheck beta_check(const Series& s, const std::string& claim, const std::string& paper, double paper_value) {
  ClaimCheck c;
  c.claim = claim;
  c.subject = s.label;
  c.paper = paper;
  c.measured = s.fit->beta;
  const double spread = s.beta_replica_spread;
  c.sigma = beta_sigma(s);
  c.measured_text = format_with_error(s.fit->beta, s.fit->beta_err, " +- ");
  if (!std::isnan(spread))
    c.measured_text += ", spread " + format_value(spread, 2) + " over " + std::to_string(s.replica_fits) + " replicas";
  const std::string quality = fit_quality(s);
  if (quality != "ok")
    c.verdict = "not judged: " + quality;
  else {
    judge(c, paper_value);
    append_chi2_scaled_z(c, (s.fit->beta - paper_value) / beta_sigma_chi2_scaled(s), {beverloo_chi2_scale(s)});
  }
  return c;
}

/// A bound the paper states as "k < 1": agrees when the value is below it or within
/// kClaimAgreeSigmas sigma above it.
void judge_below(ClaimCheck& c, double bound) {
  if (!(c.sigma > 0) || !std::isfinite(c.measured)) {
    c.verdict = "not judged: no error";
    return;
  }
  c.judged = true;
  const double z = (c.measured - bound) / c.sigma;
  c.agrees = z <= kClaimAgreeSigmas;
  c.verdict = c.measured <= bound ? std::string("agrees (below it)")
                                  : std::string(c.agrees ? "agrees" : "differs") + " (z = " + z_text(z) + " above it)";
}

/// The relative sigma of a held fit's C: the larger of its error and the replicas' spread of ln C.
double held_C_rel_sigma(const BeverlooFit& fit, double log_C_replica_spread) {
  return std::isnan(log_C_replica_spread) ? fit.C_err / fit.C : std::max(fit.C_err / fit.C, log_C_replica_spread);
}

}  // namespace beverloo::claims
