#pragma once
/// \file verdict.h
/// \brief What every check of the paper's claims shares (reports/claims/*.cpp): which series
/// the paper's statements are about, the verdict rules (a value, a direction, no change, a
/// bound; kClaimAgreeSigmas in paper_claims.h), the chi2_red-scaled second z, and the sigma of an
/// exponent or a held fit's C. Internal to the claims table.
#include <string>
#include <vector>

#include "reports/campaign_fits.h"
#include "reports/paper_claims.h"

namespace beverloo::claims {

bool at_right_angle(const Series& s);

/// A simulated flow at theta_w = 90 (the paper's exponents and C are stated for that hopper).
bool simulated_flow(const Series& s);

/// z with one decimal, as every verdict prints it.
std::string z_text(double z);

/// The verdict of measured against the paper's value with the measurement's sigma.
void judge(ClaimCheck& c, double paper_value);

/// The verdict on a claimed direction: z, the measured change in sigma, positive in the claimed
/// direction (`claimed`, e.g. "falls"; `opposite` the other way). Beyond kClaimAgreeSigmas either
/// way it is judged; within it, "not resolved".
void judge_direction(ClaimCheck& c, double z, const char* claimed, const char* opposite);

/// The verdict on a claimed absence of change (a plateau): z, the measured change in sigma,
/// positive for a rise. Within kClaimAgreeSigmas it agrees; beyond, it differs and says which way.
void judge_no_change(ClaimCheck& c, double z);

/// A bound the paper states as "k < 1": agrees when the value is below it or within
/// kClaimAgreeSigmas sigma above it.
void judge_below(ClaimCheck& c, double bound);

/// Appended to a judged verdict where a fit's chi2_red exceeds 1: the z of the same comparison
/// with each fit's error scaled by sqrt(chi2_red), and those factors.
void append_chi2_scaled_z(ClaimCheck& c, double z_scaled, const std::vector<double>& scales);

/// The sigma of a series' exponent for a verdict: the larger of the fit error and the spread
/// over replicas (the fit error alone without replicas).
double beta_sigma(const Series& s);

/// chi2_error_scale (fit.h) of a series' Beverloo fit.
double beverloo_chi2_scale(const Series& s);

/// beta_sigma with the fit's error scaled by beverloo_chi2_scale (the spread over replicas as it is).
double beta_sigma_chi2_scaled(const Series& s);

/// An exponent of a series: its fit's beta with beta_sigma.
ClaimCheck beta_check(const Series& s, const std::string& claim, const std::string& paper, double paper_value);

/// The relative sigma of a held fit's C: the larger of its error and the replicas' spread of ln C.
double held_C_rel_sigma(const BeverlooFit& fit, double log_C_replica_spread);

}  // namespace beverloo::claims
