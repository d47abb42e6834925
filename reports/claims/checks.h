#pragma once
/// \file checks.h
/// \brief The groups of checks check_paper_claims (paper_claims.h) runs, one file each: the
/// exponents of the limits and the experiments (exponent_claims.cpp), lambda_c, 1/b and
/// lambda_c's fall with the angle (crossover_claims.cpp), Fig. 6 read at one lambda and its
/// force ratio (angle_claims.cpp), k and C as the paper fits them with beta held, and the
/// limits' prefactor ratio (stiffness_claims.cpp). Each appends its checks to `out` in the
/// paper's order.
#include <vector>

#include "reports/campaign_fits.h"
#include "reports/paper_claims.h"

namespace beverloo::claims {

void limit_exponents(const CampaignFits& fits, bool friction_only, std::vector<ClaimCheck>& out);
void limit_independence(const CampaignFits& fits, bool friction_only, int dimension, std::vector<ClaimCheck>& out);
void crossover_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
/// C(drag) / C(friction) of the two limits of one system at N = 1600, free and with beta held.
void prefactor_ratio_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void theta_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void one_lambda_theta_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void force_ratio_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
/// Fig. 7b (friction only, drag = false) or 7c (drag only)'s corners.
void heatmap_k_checks(const CampaignFits& fits, bool drag, std::vector<ClaimCheck>& out);
void hard_limit_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void rigid_limit_model_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
/// Fig. 7a's C at the stiffest E_sp against the softest, beta held, per limit.
void prefactor_softness_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void prefactor_growth_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);
void experiment_checks(const CampaignFits& fits, std::vector<ClaimCheck>& out);

}  // namespace beverloo::claims
