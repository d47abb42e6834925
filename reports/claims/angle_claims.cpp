// Fig. 6 without a crossover fit: beta read at one lambda against the angle, and Fig. 6b's
// drag-to-friction force ratio as the angle falls.
#include "reports/claims/checks.h"
#include "reports/claims/verdict.h"

#include <cmath>
#include <map>
#include <optional>

#include "reports/crossover_groups.h"
#include "reports/number_format.h"
#include "reports/series_fits.h"

namespace beverloo::claims {

/// Fig. 6b: the drag-to-friction force ratio |F_zeta| / |F_mu| at lambda = 1e-2 rises as
/// theta_w falls, and "in the low-theta_w limit (theta_w <= 30 deg) the ratio stops increasing".
/// Read per angle by force_ratio_at_paper_lambda (fitted or not: a ratio needs no fit), checked
/// as r(theta_w) / r(90), a direction as lambda_c's fall is, and below 30 deg as r(theta_w) /
/// r(30), which agrees when it lies within kClaimAgreeSigmas sigma of 1 (sigma of the log of
/// the ratio, from both angles' errors; none for a series of one run from an engine before
/// force_ratio_err).
void force_ratio_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out) {
  for (const auto& [family, by_theta] : angle_families(fits.crossovers, /*fitted_only=*/false)) {
    std::map<double, std::pair<const Crossover*, ForceRatioAtLambda>> ratio;
    for (const auto& [theta, g] : by_theta)
      if (const auto r = force_ratio_at_paper_lambda(*g)) ratio.emplace(theta, std::pair{g, *r});
    auto compare = [&](double theta, double reference, bool plateau) {
      const auto at = ratio.find(theta), ref = ratio.find(reference);
      if (at == ratio.end() || ref == ratio.end()) return;
      const ForceRatioAtLambda &a = at->second.second, &b = ref->second.second;
      ClaimCheck c;
      c.claim = plateau ? "Fig. 6b: the force ratio |F_zeta| / |F_mu| at lambda = 1e-2 stops rising below theta_w = 30 deg: "
                          "r(theta_w) / r(30)"
                        : "Fig. 6b: the force ratio |F_zeta| / |F_mu| at lambda = 1e-2 rises as theta_w falls: r(theta_w) / r(90)";
      c.subject = at->second.first->label + " at theta_w = " + format_value(theta, 3);
      c.paper = plateau ? "~1 (a plateau)" : "> 1";
      double log_ratio = std::log(a.mean / b.mean);
      double log_sigma = std::hypot(a.err / a.mean, b.err / b.mean);
      // Both read as they are at common widths: the ratio of the two angles width by width (it
      // grows with w, by 40 % over the DP campaign's widths, which the means' standard errors
      // would count as scatter), its log's mean over those widths. Its sigma is the larger of
      // the standard error over the widths (two or more) and the one the runs' own errors over
      // time give: three widths that happen to agree closely do not make a sharp ratio.
      std::vector<double> paired;
      double own_var = 0;
      bool own_errors = true;
      if (a.series && b.series)
        for (const auto& [w, r] : a.series->force_ratio.by_w)
          if (const auto other = b.series->force_ratio.by_w.find(w); other != b.series->force_ratio.by_w.end()) {
            paired.push_back(std::log(r / other->second));
            const auto ea = a.series->force_ratio.by_w_err.find(w), eb = b.series->force_ratio.by_w_err.find(w);
            if (ea == a.series->force_ratio.by_w_err.end() || eb == b.series->force_ratio.by_w_err.end())
              own_errors = false;
            else
              own_var += std::pow(ea->second / r, 2) + std::pow(eb->second / other->second, 2);
          }
      own_errors = own_errors && !paired.empty();
      std::string width_text;
      if (paired.size() >= 2 || own_errors) {
        log_ratio = sample_mean(paired);
        const double scatter = paired.size() >= 2 ? sample_sd(paired) / std::sqrt(paired.size()) : NAN;
        const double own = own_errors ? std::sqrt(own_var) / paired.size() : NAN;
        log_sigma = std::fmax(scatter, own);  // fmax: the one there is when the other is NaN
        width_text = "; width by width over " + std::to_string(paired.size()) +
                     (paired.size() == 1 ? " width" : " widths") +
                     (own_errors && !(scatter > own) ? ", sigma from the runs' errors over time"
                                                     : ", sigma from the scatter over the widths");
      }
      c.measured = std::exp(log_ratio);
      c.sigma = c.measured * log_sigma;
      auto read = [](const ForceRatioAtLambda& r) {
        return (std::isnan(r.err) ? format_value(r.mean, 3) + " (one run, no error)" : format_with_error(r.mean, r.err, " +- ")) +
               (std::fabs(std::log10(r.lambda / kForceRatioLambda)) < 1e-6 ? std::string()
                                                                         : " at lambda = " + format_value(r.lambda, 2));
      };
      c.measured_text = (std::isnan(c.sigma) ? format_value(c.measured, 3) : format_with_error(c.measured, c.sigma, " +- ")) +
                        " (" + read(a) + " against " + read(b) + " at " + format_value(reference, 3) + " deg" +
                        width_text + ")";
      if (!(log_sigma > 0)) {
        c.verdict = "not judged: no error (a series of one run at an angle, from an engine before force_ratio_err)";
      } else if (plateau) {
        judge_no_change(c, log_ratio / log_sigma);
      } else {
        judge_direction(c, log_ratio / log_sigma, "rises", "falls");
      }
      out.push_back(c);
    };
    for (auto it = ratio.rbegin(); it != ratio.rend(); ++it)  // from the flat hopper down
      if (it->first < 90) compare(it->first, 90, false);
    for (auto it = ratio.rbegin(); it != ratio.rend(); ++it)
      if (it->first < 30) compare(it->first, 30, true);
  }
}

namespace {
bool same_lambda(double a, double b) { return std::fabs(std::log10(a / b)) < 1e-6; }
}  // namespace

/// Fig. 6a read at one lambda, for the groups without a crossover fit (a campaign of one lambda
/// and a few widths per angle: a DP beta(lambda) at every angle is a cluster campaign). lambda_c
/// falls as theta_w falls, so the sigmoid moves to smaller lambda and, at a lambda two angles
/// share, beta falls with theta_w: beta(theta_w) - beta(90), whether or not 90 deg has enough
/// lambdas for a crossover fit of its own (its series' beta at that lambda is compared, not
/// its sigmoid), a direction judged beyond
/// kClaimAgreeSigmas sigma. And where the paper states lambda_c(theta_w), its Eq. 2 with the
/// plateaus d - 1/2, d - 3/2 and its 0 < 1/b < 1 puts beta(lambda) between d - 1 (1/b -> 0)
/// and d - 1 - tanh(log10(lambda / lambda_c)) / 2 (1/b = 1): above the midpoint d - 1 where
/// lambda < lambda_c, below it where lambda > lambda_c; agrees when beta lies within
/// kClaimAgreeSigmas sigma of that interval (as the 1/b check). Both assume what the paper's
/// plateaus fix: measured limits away from 3/2 and 1/2 move the midpoint (docs/paper.md).
void one_lambda_theta_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out) {
  auto crossover_fitted = [](const Crossover& g) { return g.fit || g.fit_free; };
  // a series whose fit is not determined (fit_quality) gets a row that says so, not a verdict
  auto undetermined = [](const Series& s) {
    const std::string q = fit_quality(s);
    return q == "ok" ? std::string() : "not judged: " + s.label + ": " + q;
  };
  for (const auto& [family, by_theta] : angle_families(fits.crossovers, /*fitted_only=*/false)) {
    const auto right = by_theta.find(90.0);
    // an angle with a sigmoid is read by its lambda_c against 90 deg's; without one at 90 deg
    // there is no such ratio, and every angle is read at each lambda
    const bool right_fitted = right != by_theta.end() && crossover_fitted(*right->second);
    for (auto it = by_theta.rbegin(); it != by_theta.rend(); ++it) {  // from the flat hopper down
      const auto& [theta, g] = *it;
      if (crossover_fitted(*g) && right_fitted) continue;
      for (const Series* s : g->finite) {
        if (!s->fit) continue;
        if (theta < 90 && right != by_theta.end()) {
          for (const Series* r : right->second->finite) {
            if (!r->fit || !same_lambda(r->lambda, s->lambda)) continue;
            ClaimCheck c;
            c.claim = "Fig. 6a at one lambda: lambda_c falls as theta_w falls, so beta at a lambda both angles share falls: "
                      "beta(theta_w) - beta(90)";
            c.subject = g->label + " at theta_w = " + format_value(theta, 3) + ", lambda = " + format_value(s->lambda, 3);
            c.paper = "< 0 (lambda_c 5e-2 at 90 deg, 6e-3 at 20)";
            c.measured = s->fit->beta - r->fit->beta;
            c.sigma = std::hypot(beta_sigma(*s), beta_sigma(*r));
            c.measured_text = format_with_error(c.measured, c.sigma, " +- ") + " (" +
                              format_with_error(s->fit->beta, s->fit->beta_err, " +- ") + " against " +
                              format_with_error(r->fit->beta, r->fit->beta_err, " +- ") + " at 90 deg)";
            const std::string why_not = undetermined(*s).empty() ? undetermined(*r) : undetermined(*s);
            if (!why_not.empty()) {
              c.verdict = why_not;
            } else if (!(c.sigma > 0)) {
              c.verdict = "not judged: no error";
            } else {
              judge_direction(c, -c.measured / c.sigma, "falls", "rises");
              append_chi2_scaled_z(c, c.measured / std::hypot(beta_sigma_chi2_scaled(*s), beta_sigma_chi2_scaled(*r)),
                                   {beverloo_chi2_scale(*s), beverloo_chi2_scale(*r)});
            }
            out.push_back(c);
          }
        }
        const std::optional<double> lambda_c = paper_lambda_c_at_angle(s->dimension, theta);
        if (!lambda_c) continue;
        const auto [lo, hi] = paper_beta_interval(s->dimension, s->lambda, *lambda_c);
        ClaimCheck c;
        c.claim = "Fig. 6a at one lambda: beta lies on the side of the midpoint d - 1 that the paper's lambda_c(theta_w) puts "
                  "it (Eq. 2 with its plateaus and 0 < 1/b < 1)";
        c.subject = g->label + " at theta_w = " + format_value(theta, 3) + ", lambda = " + format_value(s->lambda, 3);
        c.paper = format_value(lo, 3) + " .. " + format_value(hi, 3) + " (lambda_c ~" + format_value(*lambda_c, 2) + ")";
        c.measured = s->fit->beta;
        c.sigma = beta_sigma(*s);
        c.measured_text = format_with_error(s->fit->beta, s->fit->beta_err, " +- ");
        if (!std::isnan(s->beta_replica_spread))
          c.measured_text += ", spread " + format_value(s->beta_replica_spread, 2) + " over " +
                             std::to_string(s->replica_fits) + " replicas";
        if (const std::string why_not = undetermined(*s); !why_not.empty()) {
          c.verdict = why_not;
        } else if (!(c.sigma > 0)) {
          c.verdict = "not judged: no error";
        } else {
          const double nearest = std::clamp(c.measured, lo, hi);
          const double z = std::fabs(c.measured - nearest) / c.sigma;
          c.judged = true;
          c.agrees = z <= kClaimAgreeSigmas;
          c.verdict = std::string(c.agrees ? "agrees" : c.measured > hi ? "differs (above" : "differs (below") +
                      (c.agrees ? " (z = " : ", z = ") + z_text(z) + " from the interval)";
          if (z > 0)  // inside the interval there is nothing to scale
            append_chi2_scaled_z(c, (c.measured - nearest) / beta_sigma_chi2_scaled(*s), {beverloo_chi2_scale(*s)});
        }
        out.push_back(c);
      }
    }
  }
}

}  // namespace beverloo::claims
