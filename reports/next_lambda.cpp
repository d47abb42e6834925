#include "next_lambda.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace beverloo {

namespace {

using Mat2 = Eigen::Matrix2d;
using Vec2 = Eigen::Vector2d;

/// dbeta/d(x, b) of beta = d - 1 - tanh((log10 lambda - x) / b) / 2 (the dimension drops out).
Vec2 gradient(double x, double b, double lambda) {
  const double u = (std::log10(lambda) - x) / b;
  const double t = std::tanh(u), sech2 = 1 - t * t;
  return Vec2(0.5 * sech2 / b, 0.5 * sech2 * u / b);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::vector<double> free_candidate_log10_lambdas(const std::vector<double>& have, double lambda_lo, double lambda_hi,
                                                 int per_decade) {
  if (!(lambda_lo > 0) || !(lambda_hi >= lambda_lo) || per_decade < 1)
    throw FitError("the candidate lambdas need 0 < lambda_lo <= lambda_hi and per_decade >= 1");
  std::vector<double> have_log;
  for (double l : have)
    if (l > 0 && std::isfinite(l)) have_log.push_back(std::log10(l));
  const double step = 1.0 / per_decade;
  const int k_lo = static_cast<int>(std::ceil(std::log10(lambda_lo) * per_decade - 1e-9));
  const int k_hi = static_cast<int>(std::floor(std::log10(lambda_hi) * per_decade + 1e-9));
  if (k_hi - k_lo > 100000) throw FitError("more than 100000 candidate lambdas");
  std::vector<double> out;
  for (int k = k_lo; k <= k_hi; ++k) {
    const double log_l = static_cast<double>(k) / per_decade;
    if (std::none_of(have_log.begin(), have_log.end(), [&](double h) { return std::fabs(h - log_l) < 0.5 * step; }))
      out.push_back(log_l);
  }
  return out;
}

CrossoverAdvice next_lambda(int /*dimension*/, const CrossoverFit& fit, const std::vector<double>& lambda,
                            const std::vector<double>& beta_err, double lambda_lo, double lambda_hi, int per_decade,
                            const CrossoverTargets& targets) {
  if (lambda.size() != beta_err.size() || lambda.size() < 3)
    throw FitError("the design needs the group's series (at least 3 finite lambda, each with its beta error)");
  const std::vector<double> candidates = free_candidate_log10_lambdas(lambda, lambda_lo, lambda_hi, per_decade);
  const double x = fit.log10_lambda_c, b = fit.b;
  if (!std::isfinite(x) || !(b > 0)) throw FitError("the crossover fit has no finite lambda_c and width b > 0");
  Mat2 F = Mat2::Zero();
  std::vector<double> errs;
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    if (!(lambda[i] > 0) || !std::isfinite(lambda[i]) || !(beta_err[i] > 0)) continue;
    const Vec2 g = gradient(x, b, lambda[i]);
    F += g * g.transpose() / (beta_err[i] * beta_err[i]);
    errs.push_back(beta_err[i]);
  }
  if (errs.size() < 3) throw FitError("fewer than 3 finite lambda with a beta error");
  const Eigen::FullPivLU<Mat2> lu(F);
  if (!lu.isInvertible() || !(lu.rcond() > 1e-12)) {
    // The step is so sharp that no series sits on it (sech^2 u ~ 0 at every point): the series
    // cannot tell lambda_c and b apart, and a new series helps only on the step itself. Take
    // the free candidate nearest to the fitted lambda_c; its effect cannot be predicted (NaN).
    CrossoverAdvice a;
    a.log10_lambda_c_err_now = fit.log10_lambda_c_err;
    a.b_err_now = fit.b_err;
    double best = INFINITY;
    for (const double log_l : candidates) {
      if (!(std::fabs(log_l - x) < best)) continue;  // strict: ties to the smaller
      best = std::fabs(log_l - x);
      a.next = NextLambda{std::pow(10.0, log_l), NAN, NAN};
    }
    if (!a.next) throw FitError("the step of beta(lambda) lies between series and no candidate lambda is free near it");
    return a;
  }
  const Mat2 cov = lu.inverse();
  // the fit's reported errors over the information's: applied to the predictions too
  const double scale_x = fit.log10_lambda_c_err > 0 ? fit.log10_lambda_c_err / std::sqrt(cov(0, 0)) : 1;
  const double scale_b = fit.b_err > 0 ? fit.b_err / std::sqrt(cov(1, 1)) : 1;
  CrossoverAdvice a;
  a.log10_lambda_c_err_now = fit.log10_lambda_c_err > 0 ? fit.log10_lambda_c_err : std::sqrt(cov(0, 0));
  a.b_err_now = fit.b_err > 0 ? fit.b_err : std::sqrt(cov(1, 1));
  const bool any_target = targets.log10_lambda_c_err || targets.b_err;
  a.targets_met = any_target && (!targets.log10_lambda_c_err || a.log10_lambda_c_err_now <= *targets.log10_lambda_c_err) &&
                  (!targets.b_err || a.b_err_now <= *targets.b_err);
  if (a.targets_met) return a;
  // phi's weights in the information's units: a target given, else the present error
  const double s_x = (targets.log10_lambda_c_err ? *targets.log10_lambda_c_err : (any_target ? INFINITY : a.log10_lambda_c_err_now)) / scale_x;
  const double s_b = (targets.b_err ? *targets.b_err : (any_target ? INFINITY : a.b_err_now)) / scale_b;
  auto phi = [&](const Mat2& c) { return c(0, 0) / (s_x * s_x) + c(1, 1) / (s_b * s_b); };
  const double phi_now = phi(cov), sigma = median(errs);
  double best = -INFINITY;
  for (const double log_l : candidates) {
    const double lc = std::pow(10.0, log_l);
    const Vec2 g = gradient(x, b, lc);
    const Eigen::FullPivLU<Mat2> after_lu(F + g * g.transpose() / (sigma * sigma));
    if (!after_lu.isInvertible()) continue;
    const Mat2 after = after_lu.inverse();
    const double score = phi_now - phi(after);
    if (score > best) {  // strict: ties go to the smaller lambda
      best = score;
      a.next = NextLambda{lc, std::sqrt(after(0, 0)) * scale_x, std::sqrt(after(1, 1)) * scale_b};
    }
  }
  if (!a.next) throw FitError("no candidate lambda in the range given that the group does not have");
  return a;
}

}  // namespace beverloo
