#include "paper_claims.h"

#include <cstdio>
#include <sstream>

#include "core/text_escape.h"
#include "reports/claims/checks.h"

namespace beverloo {

std::vector<ClaimCheck> check_paper_claims(const CampaignFits& fits) {
  using namespace claims;
  std::vector<ClaimCheck> out;
  limit_exponents(fits, true, out);
  limit_exponents(fits, false, out);
  for (int d : {2, 3}) {
    limit_independence(fits, true, d, out);
    limit_independence(fits, false, d, out);
  }
  crossover_checks(fits, out);
  prefactor_ratio_checks(fits, out);
  prefactor_softness_checks(fits, out);
  theta_checks(fits, out);
  one_lambda_theta_checks(fits, out);
  force_ratio_checks(fits, out);
  heatmap_k_checks(fits, /*drag=*/false, out);
  heatmap_k_checks(fits, /*drag=*/true, out);
  hard_limit_checks(fits, out);
  rigid_limit_model_checks(fits, out);
  prefactor_growth_checks(fits, out);
  experiment_checks(fits, out);
  return out;
}

std::string claims_markdown(const std::vector<ClaimCheck>& checks) {
  std::ostringstream md;
  md << "| claim | checked on | paper | beverloo | verdict |\n|---|---|---|---|---|\n";
  for (const ClaimCheck& c : checks)
    md << "| " << markdown_cell(c.claim) << " | " << markdown_cell(c.subject) << " | " << markdown_cell(c.paper) << " | "
       << markdown_cell(c.measured_text) << " | " << markdown_cell(c.verdict) << " |\n";
  return md.str();
}

std::string claims_csv(const std::vector<ClaimCheck>& checks) {
  std::ostringstream csv;
  csv << "claim,checked_on,paper,measured,sigma,measured_text,verdict,judged,agrees\n";
  char num[2][32];
  for (const ClaimCheck& c : checks) {
    std::snprintf(num[0], sizeof num[0], "%.10g", c.measured);
    std::snprintf(num[1], sizeof num[1], "%.10g", c.sigma);
    csv << csv_field(c.claim) << ',' << csv_field(c.subject) << ',' << csv_field(c.paper) << ',' << num[0] << ','
        << num[1] << ',' << csv_field(c.measured_text) << ',' << csv_field(c.verdict) << ',' << (c.judged ? 1 : 0) << ','
        << (c.agrees ? 1 : 0) << '\n';
  }
  return csv.str();
}

}  // namespace beverloo
