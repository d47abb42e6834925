#pragma once
/// \file fit.h
/// \brief Weighted nonlinear least squares (GSL multifit_nlinear, trust region) for the two laws
/// of physics.md 8:
///   Beverloo   Q(w) = C (w - k)^beta,                        k kept below the smallest w
///   crossover  beta(lambda) = d - 1 - tanh[(1/b) log10(lambda/lambda_c)] / 2
/// Weights are 1/sigma^2 from the data's errors, so the covariance (J^T W J)^-1 gives the
/// parameters' standard errors directly (not rescaled by chi^2; chi^2_red is reported beside).
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace beverloo {

/// Input that cannot be fitted (too few points, no flow, constant data): a message, never NaN.
class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BeverlooFit {
  double C = 0, C_err = 0, k = 0, k_err = 0, beta = 0, beta_err = 0;
  double chi2_red = 0;
  int points = 0;  ///< flowing points used
  double w_min = NAN, w_max = NAN;  ///< the smallest and largest width used
  /// Widths used that lie below k: the authors' |C| |w - k|^beta (the bounded and held fits)
  /// folds them onto the law's mirror image, so such a fit describes no flow there. Always 0 in
  /// beverloo's free fit, whose k stays below every width.
  int folded_points = 0;
};

/// sqrt(chi2_red) where a weighted fit's reduced chi^2 exceeds 1, else 1 (also when chi2_red is
/// not finite: no degrees of freedom left): the factor by which a curve that misses its points by
/// more than their errors understates its own errors (the Particle Data Group's scale factor for
/// averages of inconsistent measurements). Used for Beverloo and crossover fits alike.
inline double chi2_error_scale(double chi2_red) {
  return std::isfinite(chi2_red) && chi2_red > 1 ? std::sqrt(chi2_red) : 1.0;
}

/// "" when no width is folded; else e.g. "k above 1 of its 7 widths (4 .. 10): |w - k| folds it".
std::string folded_widths_note(const BeverlooFit& f);

/// w, Q, Q_err of flowing points (Q > 0, Q_err > 0). Needs at least 4 points (3 parameters + 1).
BeverlooFit fit_beverloo(const std::vector<double>& w, const std::vector<double>& Q, const std::vector<double>& Q_err);

/// The Beverloo fit as the paper's authors made it (YUXUANCHENG/Matlab-process, oop/CLI/CLI_hopper.m
/// helper_plotFlowRate2, fitmode 3; oop/paper.m ~510-512): unweighted least squares of
/// |C (w - k)^beta| within bounds, over 2 < w < 19. Their C bound, [0, 1] in their flow-rate
/// unit, is [0, kAuthorsFlowUnit] in sigma_avg^2/t0. A labelled option, never the default.
struct BoundedFitOptions {
  double C_lo = 0, C_hi = 316.4, k_lo = 0.5, k_hi = 5, beta_lo = 0.4, beta_hi = 1.58;
  double w_lo = 2, w_hi = 19;  ///< widths used: w_lo < w < w_hi
  static BoundedFitOptions authors() { return {}; }
};
/// Q in sigma_avg^2/t0 per unit of the authors' flow_rate (10 x mean exits per step,
/// FileReader.m readFlowR; dt 0.005 code times, t0 = 19.596, mean particle 0.807 sigma_avg^2)
inline constexpr double kAuthorsFlowUnit = 316.4;

struct BoundedBeverlooFit {
  BeverlooFit fit;  ///< errors from the unweighted residuals (s^2 (J^T J)^-1), as MATLAB's fit reports
  bool C_at_bound = false, k_at_bound = false, beta_at_bound = false;
};
/// Needs at least 4 points in the width range.
BoundedBeverlooFit fit_beverloo_bounded(const std::vector<double>& w, const std::vector<double>& Q,
                                        const BoundedFitOptions& o);

/// The Beverloo fit with beta held fixed, as the authors fitted their Fig. 2 and Appendix B
/// (CLI_hopper.m helper_plotFlowRate2, fitmodes 1 and 2: beta = 1/2 or 3/2, |C (w - k)^beta|
/// unweighted, no bounds, over the widths of `o` and only points with Q above 0.01 of their flow
/// unit, i.e. Q > 3.164 sigma_avg^2/t0). k and C with errors from the residuals; beta_err = 0.
/// Needs at least 3 points.
BeverlooFit fit_beverloo_fixed_beta(const std::vector<double>& w, const std::vector<double>& Q, double beta,
                                    const BoundedFitOptions& o);

struct CrossoverFit {
  double lambda_c = 0, lambda_c_err = 0, log10_lambda_c = 0, log10_lambda_c_err = 0;
  double b = 0, b_err = 0;
  double chi2_red = 0;
  int points = 0;
  /// With free plateaus (fit_crossover_free_plateaus): beta's limits as lambda -> 0 and -> inf;
  /// with the paper's fixed plateaus these are d - 1/2 and d - 3/2 and their errors 0.
  double beta_0 = 0, beta_0_err = 0, beta_inf = 0, beta_inf_err = 0;
  bool plateaus_free = false;
};

/// beta(lambda) for finite lambda > 0 in dimension d. Needs at least 3 points spanning the step.
CrossoverFit fit_crossover(int d, const std::vector<double>& lambda, const std::vector<double>& beta,
                           const std::vector<double>& beta_err);

/// The same law with its plateaus free: beta = beta_inf + (beta_0 - beta_inf)(1 - tanh[(1/b)
/// log10(lambda/lambda_c)])/2, four parameters, at least 5 points. The paper fixes the plateaus
/// at d - 1/2 and d - 3/2; a series whose limits were measured elsewhere is fitted both ways.
CrossoverFit fit_crossover_free_plateaus(const std::vector<double>& lambda, const std::vector<double>& beta,
                                         const std::vector<double>& beta_err);

double beverloo_model(double w, double C, double k, double beta);
double crossover_model(int d, double lambda, double lambda_c, double b);

}  // namespace beverloo
