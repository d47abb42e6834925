#pragma once
/// \file paper_claims.h
/// \brief The paper's quantitative claims that a campaign's own fits can test (docs/paper.md
/// has every claim; this is the part a report can check by itself): the exponents in both
/// dissipation limits (d - 1/2 with friction only, d - 3/2 with drag only, for SP and DP), that
/// the exponent of a limit does not depend on the model or its stiffness, nor on N >= 800,
/// lambda_c and the stretching exponent of beta(lambda), the fall of lambda_c with the hopper
/// angle (Fig. 6; read at one lambda where no angle has a crossover fit: beta falls with the
/// angle, and lies where the paper's Eq. 2 with its lambda_c(theta_w) puts it) and the rise of the
/// drag-to-friction force ratio as it falls (Fig. 6b), the ratio of the prefactors C of the two limits (free, and with beta held
/// as the paper fits) and the held C's independence of E_sp (Fig. 7a), the corners of Fig. 7b's and
/// 7c's k maps (smooth DP in each limit, k with beta held), Appendix B's hard-particle limit (SP at
/// E_sp >= 1e5: k of each limit with beta held, the ratio of their C; rigid DP against hard SP,
/// Q width by width), Appendix C's prefactor against N (Fig. C(b)), and the experiments' beta and k.
/// Each check names the series or group it read, the paper's value, the measured one with its
/// error (and the replicas' spread where there is one), and a verdict by one stated rule. The
/// paper's values carry no errors ("~" in its text), so the rule uses the measurement's: agree
/// when |measured - paper| <= 2 sigma, sigma the larger of the fit's error and the replicas'
/// spread (a direction, such as lambda_c's fall, is claimed beyond 2 sigma). Nothing is
/// rescaled and no fit is made here. The checks live in reports/claims/ (checks.h lists them by
/// file; verdict.h has the rules they share).
#include <string>
#include <vector>

#include "reports/campaign_fits.h"

namespace beverloo {

struct ClaimCheck {
  std::string claim;     ///< the paper's claim in a few words, with where it says so
  std::string subject;   ///< the series or group it was checked on (its label)
  std::string paper;     ///< the paper's value, as the paper states it
  double measured = 0;   ///< beverloo's value
  double sigma = 0;      ///< its error for the verdict: max(fit error, replicas' spread)
  std::string measured_text;  ///< value +- fit error, and the spread over replicas if any
  std::string verdict;   ///< "agrees (z = 0.8)", "differs (z = 3.1)", or why it is not judged
  bool judged = false;   ///< false: the fit is not determined, so no verdict
  bool agrees = false;
};

/// The claims the campaign's series and beta(lambda) groups can test, in the paper's order.
std::vector<ClaimCheck> check_paper_claims(const CampaignFits& fits);

/// The same as a Markdown table and as CSV (text cells escaped for each).
std::string claims_markdown(const std::vector<ClaimCheck>& checks);
std::string claims_csv(const std::vector<ClaimCheck>& checks);

/// The verdict rule: |measured - paper| / sigma, "agrees" at most kClaimAgreeSigmas.
inline constexpr double kClaimAgreeSigmas = 2.0;

}  // namespace beverloo
