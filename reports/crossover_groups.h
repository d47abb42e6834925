#pragma once
/// \file crossover_groups.h
/// \brief beta(lambda) groups: the series that differ only in lambda, each with its lambda = 0
/// and lambda = inf limits, fitted with the paper's fixed plateaus and with free ones. Two
/// lambda axes: the text's (zeta and mu at a fixed dissipation scale) and the authors' (drag as
/// a rate times the mass, both of their branches in one group).
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "campaign_fits.h"

namespace beverloo {

/// The groups of the fitted series; base_job_of: each series' job without the dissipation
/// parameters (CampaignRuns), which tells groups with equal labels apart.
std::vector<Crossover> crossover_groups(const std::vector<Series>& series,
                                        const std::map<std::string, nlohmann::json>& base_job_of);

/// The sigma of log10 lambda_c that verdicts and error bars use: the larger of the fit's error
/// and the spread over the replicas' own fits (the fit's error alone without replicas), as an
/// exponent's sigma is the larger of its error and its spread.
double log10_lambda_c_sigma(const CrossoverFit& fit, const Crossover::ReplicaSpread& spread);
/// chi2_error_scale (fit.h) of a crossover fit's chi2_red.
double chi2_scale(const CrossoverFit& fit);
/// log10_lambda_c_sigma with the fit's error multiplied by chi2_scale. The claims table shows
/// the z it gives beside each lambda_c verdict; the verdict itself keeps log10_lambda_c_sigma.
double log10_lambda_c_sigma_chi2_scaled(const CrossoverFit& fit, const Crossover::ReplicaSpread& spread);

/// "spread 0.15 in log10 over 3 replicas", or "" without a spread: how every table says it.
std::string lambda_c_spread_phrase(const Crossover::ReplicaSpread& spread);

/// Where beta(lambda) crosses d - 1, the paper's sigmoid's midpoint by construction, without a
/// sigmoid: log10 lambda interpolated linearly between the two measured lambdas that bracket the
/// crossing (the first such pair from below, determined free fits), its sigma from the two
/// exponents' errors, and its run-to-run spread: the sample standard deviation of each replica's
/// own crossing (from the replicas' own fits of the series that have them; NaN below two
/// replicas that cross), and the interpolation's own error: how far the crossing moves when
/// beta(log10 lambda) is the parabola through the bracketing pair and one neighbour instead of
/// their chord (the larger of the one or two parabolas the neighbours give; NaN without a
/// neighbour). That is the next term of the interpolation, the one a finer lambda grid shrinks
/// (as the square of the step where beta is smooth). Nothing when the exponents never cross d - 1.
struct MidpointCrossing {
  double log10_lambda = 0, sigma = 0, lambda_lo = 0, lambda_hi = 0;
  double spread = NAN;
  double interpolation = NAN;
  /// Whether beta(lambda) turns back next to the crossing: the largest z = |step| / its error
  /// of a step from the pair to a neighbouring lambda that goes against the pair's own direction
  /// (NaN without such a step). A chord through a non-monotone stretch (the authors' SP model at
  /// 30 deg: 1.04, 0.73, then 0.95) is not what the interpolation error measures.
  double reversal_z = NAN;
  int replicas = 0;  ///< replicas whose own exponents cross d - 1
  /// The sigma of log10 lambda that verdicts and bars use: the larger of sigma and the spread
  /// (both the scatter of the exponents), with the interpolation's error added in quadrature.
  double verdict_sigma() const {
    const double scatter = std::isnan(spread) ? sigma : std::max(sigma, spread);
    return std::isnan(interpolation) ? scatter : std::hypot(scatter, interpolation);
  }
};
std::optional<MidpointCrossing> crossing_of_d_minus_1(const Crossover& g);

/// lambda_c as the paper's text states it for a hopper angle (2D: 5e-2 at 90 deg, 6e-3 at 20,
/// the plateau ~5e-3 for theta_w <= 30, read at 30); nothing elsewhere (60 deg, 3D).
std::optional<double> paper_lambda_c_at_angle(int dimension, double theta_w_deg);

/// Where the paper's Eq. 2 (plateaus d - 1/2 and d - 3/2) with 0 < 1/b < 1 puts beta at lambda
/// for a given lambda_c: between the midpoint d - 1 (1/b -> 0) and d - 1 - tanh(log10(lambda /
/// lambda_c)) / 2 (1/b = 1), as {low, high}.
std::pair<double, double> paper_beta_interval(int dimension, double lambda, double lambda_c);

/// Fig. 6b reads the force ratio |F_zeta| / |F_mu| at this lambda, for every hopper angle.
inline constexpr double kForceRatioLambda = 1e-2;

/// A group's force ratio read at kForceRatioLambda from its finite-lambda series, fitted or not
/// (Series::force_ratio), and the lambdas it was read from.
struct ForceRatioAtLambda {
  double lambda = NAN;  ///< kForceRatioLambda when bracketed (or hit), else the nearest series' lambda
  double mean = NAN, err = NAN;  ///< err NaN: a series of one run, no error
  double lambda_below = NAN, lambda_above = NAN;
  int runs = 0;
  const Series* series = nullptr;  ///< the series read as it is (nullptr when interpolated)
};
/// Interpolated linearly in log ratio against log lambda between the two series nearest to it
/// on either side within a decade (the ratio is close to proportional to lambda), its relative
/// error propagated from theirs; a series at kForceRatioLambda itself is read as it is; without
/// a bracket, the nearest series within half a decade. Nothing when none is near enough.
/// (Reading each angle at its own nearest lambda instead compared angles at lambdas up to 1.8
/// times apart, and the ratio scales with lambda: 0.010 against 0.018 in the SP campaign.)
std::optional<ForceRatioAtLambda> force_ratio_at_paper_lambda(const Crossover& g);

/// Fig. 6's families: the groups with a symmetric hopper angle that differ only in it
/// (Crossover::angle_family -> theta_w -> the family's group at that angle, the first if two).
/// Groups without a finite-lambda series (limits only) have none. fitted_only: only groups with
/// a crossover fit, with fixed or free plateaus.
std::map<std::string, std::map<double, const Crossover*>> angle_families(const std::vector<Crossover>& crossovers,
                                                                         bool fitted_only);

}  // namespace beverloo
