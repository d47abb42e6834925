#pragma once
/// \file fit.h
/// \brief Weighted nonlinear least squares (GSL multifit_nlinear, trust region) for the two laws
/// of physics.md 8:
///   Beverloo   Q(w) = C (w - k)^beta,                        k kept below the smallest w
///   crossover  beta(lambda) = d - 1 - tanh[(1/b) log10(lambda/lambda_c)] / 2
/// Weights are 1/sigma^2 from the data's errors, so the covariance (J^T W J)^-1 gives the
/// parameters' standard errors directly (not rescaled by chi^2; chi^2_red is reported beside).
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
};

/// w, Q, Q_err of flowing points (Q > 0, Q_err > 0). Needs at least 4 points (3 parameters + 1).
BeverlooFit fit_beverloo(const std::vector<double>& w, const std::vector<double>& Q, const std::vector<double>& Q_err);

struct CrossoverFit {
  double lambda_c = 0, lambda_c_err = 0, log10_lambda_c = 0, log10_lambda_c_err = 0;
  double b = 0, b_err = 0;
  double chi2_red = 0;
  int points = 0;
};

/// beta(lambda) for finite lambda > 0 in dimension d. Needs at least 3 points spanning the step.
CrossoverFit fit_crossover(int d, const std::vector<double>& lambda, const std::vector<double>& beta,
                           const std::vector<double>& beta_err);

double beverloo_model(double w, double C, double k, double beta);
double crossover_model(int d, double lambda, double lambda_c, double b);

}  // namespace beverloo
