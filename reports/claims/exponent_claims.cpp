// The exponents of the two dissipation limits against d - 1/2 and d - 3/2, their independence
// of the model, its stiffness and N, and the experiments' beta and k (Fig. 8).
#include "reports/claims/checks.h"
#include "reports/claims/verdict.h"

#include <algorithm>
#include <cmath>

#include "reports/number_format.h"
#include "reports/series_fits.h"

namespace beverloo::claims {

namespace {
bool is_limit(const Series& s, bool friction_only) { return friction_only ? s.lambda == 0 : std::isinf(s.lambda); }
}  // namespace

void limit_exponents(const CampaignFits& fits, bool friction_only, std::vector<ClaimCheck>& out) {
  for (const Series& s : fits.series) {
    if (!s.fit || !simulated_flow(s) || !is_limit(s, friction_only)) continue;
    const double d = s.dimension;
    const double value = friction_only ? d - 0.5 : d - 1.5;
    out.push_back(beta_check(
        s, friction_only ? "friction only (lambda = 0): beta = d - 1/2 (Fig. 2, 3)" : "drag only (lambda = inf): beta = d - 3/2 (Fig. 2, 3)",
        format_value(value, 2) + " (" + std::to_string(s.dimension) + "D)", value));
  }
}

namespace {
/// The two determined series of one limit, among those `same` puts together with the first and
/// that differ in what the claim is about (`differ`), whose exponents differ most, in units of
/// their combined sigma; appended as `claim` (nothing when no such pair exists).
template <class Same, class Differ>
void most_different_pair(const CampaignFits& fits, bool friction_only, int dimension, const std::string& claim,
                         Same same, Differ differ, std::vector<ClaimCheck>& out) {
  std::vector<const Series*> all;
  for (const Series& s : fits.series)
    if (s.fit && simulated_flow(s) && is_limit(s, friction_only) && s.dimension == dimension && fit_quality(s) == "ok")
      all.push_back(&s);
  // groups of series that `same` relates, each checked on its own
  std::vector<bool> used(all.size(), false);
  for (std::size_t g = 0; g < all.size(); ++g) {
    if (used[g]) continue;
    std::vector<const Series*> in;
    for (std::size_t i = g; i < all.size(); ++i)
      if (!used[i] && same(*all[g], *all[i])) in.push_back(all[i]), used[i] = true;
    const Series *a = nullptr, *b = nullptr;
    double worst = -1;
    for (std::size_t i = 0; i < in.size(); ++i)
      for (std::size_t j = i + 1; j < in.size(); ++j) {
        if (!differ(*in[i], *in[j])) continue;
        const double z = std::fabs(in[i]->fit->beta - in[j]->fit->beta) / std::hypot(beta_sigma(*in[i]), beta_sigma(*in[j]));
        if (z > worst) worst = z, a = in[i], b = in[j];
      }
    if (!a) continue;
    ClaimCheck c;
    c.claim = claim + " (" + (friction_only ? "lambda = 0" : "lambda = inf") + ", the two of " +
              std::to_string(in.size()) + " series that differ most)";
    c.subject = a->label + " / " + b->label;
    c.paper = "the same beta";
    c.measured = a->fit->beta - b->fit->beta;
    c.sigma = std::hypot(beta_sigma(*a), beta_sigma(*b));
    c.measured_text = format_with_error(c.measured, c.sigma, " +- ") + " (difference)";
    judge(c, 0);
    append_chi2_scaled_z(c, c.measured / std::hypot(beta_sigma_chi2_scaled(*a), beta_sigma_chi2_scaled(*b)),
                         {beverloo_chi2_scale(*a), beverloo_chi2_scale(*b)});
    out.push_back(c);
  }
}
}  // namespace

/// "beta does not depend on deformability or roughness" (series of one N that differ in model
/// or stiffness) and "beta does not depend on N for N > 800" (Appendix C: series that differ in
/// N alone, N >= 800).
void limit_independence(const CampaignFits& fits, bool friction_only, int dimension, std::vector<ClaimCheck>& out) {
  most_different_pair(
      fits, friction_only, dimension, "beta does not depend on deformability or roughness",
      [](const Series& a, const Series& b) { return a.N == b.N; },
      [](const Series& a, const Series& b) { return a.model != b.model || a.stiffness != b.stiffness; }, out);
  most_different_pair(
      fits, friction_only, dimension, "beta does not depend on N for N >= 800 (Appendix C)",
      [](const Series& a, const Series& b) {
        return a.N >= 800 && b.N >= 800 && a.model == b.model && a.stiffness == b.stiffness;
      },
      [](const Series& a, const Series& b) { return a.N != b.N; }, out);
}

/// The experiments (oil droplets, Fig. 8): beta ~ 0.49 and k ~ 1.5, on measured series; and
/// beverloo's own draining hoppers (drain jobs: the paper's comparison of the experiments with
/// drag-only SP, docs/experiments.md) against those values. Sigma of each: the larger of the fit
/// error and the spread over replicas. An imported simulated series is not checked: it is
/// someone else's model.
void experiment_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out) {
  for (const Series& s : fits.series) {
    const bool measured = s.provenance == "measured", simulated_drain = s.drain && s.provenance.empty();
    if (!(measured || simulated_drain) || !s.fit) continue;
    const std::string claim =
        measured ? "experiments (Fig. 8): " : "a simulated draining hopper against the experiments (Fig. 8): ";
    out.push_back(beta_check(s, claim + "beta ~ 0.49", "~0.49", 0.49));
    ClaimCheck c;
    c.claim = claim + "k ~ 1.5";
    c.subject = s.label;
    c.paper = "~1.5";
    c.measured = s.fit->k;
    c.sigma = std::isnan(s.k_replica_spread) ? s.fit->k_err : std::max(s.fit->k_err, s.k_replica_spread);
    c.measured_text = format_with_error(s.fit->k, s.fit->k_err, " +- ");
    if (!std::isnan(s.k_replica_spread))
      c.measured_text += ", spread " + format_value(s.k_replica_spread, 2) + " over " + std::to_string(s.replica_fits) + " replicas";
    const std::string quality = fit_quality(s);
    if (quality != "ok")
      c.verdict = "not judged: " + quality;
    else
      judge(c, 1.5);
    out.push_back(c);
  }
}

}  // namespace beverloo::claims
