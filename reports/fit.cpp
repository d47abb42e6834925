#include "fit.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "reports/number_format.h"

namespace beverloo {
namespace {

struct Problem {
  std::size_t n, p;
  std::function<double(std::size_t i, const double* x)> model;  ///< model value at point i
  const std::vector<double>* y;
};

int residuals(const gsl_vector* x, void* data, gsl_vector* f) {
  const Problem& pr = *static_cast<Problem*>(data);
  for (std::size_t i = 0; i < pr.n; ++i) {
    const double m = pr.model(i, x->data);
    if (!std::isfinite(m)) return GSL_EDOM;
    gsl_vector_set(f, i, m - (*pr.y)[i]);
  }
  return GSL_SUCCESS;
}

struct Solution {
  std::vector<double> x;
  std::vector<double> cov;  ///< p x p
  double chi2 = INFINITY;
  bool ok = false;
};

/// One trust-region solve from x0; weights 1/sigma^2. Jacobian by GSL's finite differences.
Solution solve(Problem& pr, const std::vector<double>& x0, const std::vector<double>& sigma) {
  Solution s;
  gsl_set_error_handler_off();
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = residuals;
  fdf.df = nullptr;
  fdf.fvv = nullptr;
  fdf.n = pr.n;
  fdf.p = pr.p;
  fdf.params = &pr;
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, pr.n, pr.p);
  std::vector<double> xv = x0, wts(pr.n);
  for (std::size_t i = 0; i < pr.n; ++i) wts[i] = 1.0 / (sigma[i] * sigma[i]);
  gsl_vector_view xview = gsl_vector_view_array(xv.data(), pr.p);
  gsl_vector_view wview = gsl_vector_view_array(wts.data(), pr.n);
  int info = 0;
  if (gsl_multifit_nlinear_winit(&xview.vector, &wview.vector, &fdf, w) == GSL_SUCCESS &&
      gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 1e-10, nullptr, nullptr, &info, w) == GSL_SUCCESS) {
    gsl_vector* f = gsl_multifit_nlinear_residual(w);  // already weighted: sqrt(w_i) r_i
    double chi2 = 0;
    gsl_blas_ddot(f, f, &chi2);
    gsl_matrix* cov = gsl_matrix_alloc(pr.p, pr.p);
    gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cov);
    s.x.assign(gsl_multifit_nlinear_position(w)->data, gsl_multifit_nlinear_position(w)->data + pr.p);
    s.cov.assign(cov->data, cov->data + pr.p * pr.p);
    gsl_matrix_free(cov);
    s.chi2 = chi2;
    s.ok = std::isfinite(chi2) && std::all_of(s.cov.begin(), s.cov.end(), [](double v) { return std::isfinite(v); });
  }
  gsl_multifit_nlinear_free(w);
  return s;
}

void check_inputs(const char* what, const std::vector<double>& x, const std::vector<double>& y,
                  const std::vector<double>& e, std::size_t min_points) {
  if (x.size() != y.size() || x.size() != e.size()) throw FitError(std::string(what) + ": inputs of different lengths");
  if (x.size() < min_points)
    throw FitError(std::string(what) + ": " + std::to_string(x.size()) + " points, need at least " +
                   std::to_string(min_points) + " (more than the parameters)");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(e[i] > 0) || !std::isfinite(y[i]) || !std::isfinite(x[i]))
      throw FitError(std::string(what) + ": point " + std::to_string(i) + " has no finite value with a positive error");
  if (*std::max_element(y.begin(), y.end()) == *std::min_element(y.begin(), y.end()))
    throw FitError(std::string(what) + ": all values equal; the law cannot be fitted to constant data");
}

}  // namespace

double beverloo_model(double w, double C, double k, double beta) { return C * std::pow(w - k, beta); }
double crossover_model(int d, double lambda, double lambda_c, double b) {
  return d - 1 - 0.5 * std::tanh(std::log10(lambda / lambda_c) / b);
}

namespace {
/// BeverlooFit's widths: the range used and how many lie below the fitted k.
void set_widths(BeverlooFit& f, const std::vector<double>& w) {
  f.points = static_cast<int>(w.size());
  f.w_min = *std::min_element(w.begin(), w.end());
  f.w_max = *std::max_element(w.begin(), w.end());
  f.folded_points = static_cast<int>(std::count_if(w.begin(), w.end(), [&](double x) { return x < f.k; }));
}
}  // namespace

std::string folded_widths_note(const BeverlooFit& f) {
  if (f.folded_points == 0) return "";
  return "k above " + std::to_string(f.folded_points) + " of its " + std::to_string(f.points) + " widths (" +
         format_value(f.w_min, 3) + " .. " + format_value(f.w_max, 3) + "): |w - k| folds " +
         (f.folded_points == 1 ? "it" : "them");
}

BeverlooFit fit_beverloo(const std::vector<double>& w, const std::vector<double>& Q, const std::vector<double>& Q_err) {
  check_inputs("Beverloo fit", w, Q, Q_err, 4);
  for (double q : Q)
    if (q <= 0) throw FitError("Beverloo fit: Q must be > 0 for every point used (leave clogged points out)");
  const double w_min = *std::min_element(w.begin(), w.end());
  // Parameters (log C, u, beta) with k = w_min - exp(u): k stays below the smallest w.
  Problem pr{w.size(), 3, [&](std::size_t i, const double* x) {
               return std::exp(x[0]) * std::pow(w[i] - (w_min - std::exp(x[1])), x[2]);
             }, &Q};
  Solution best;
  for (double k0 : {w_min - 0.5, w_min - 1.5, w_min - 3.0, 0.0, -2.0}) {  // several starts: the valley in k is long
    if (k0 >= w_min) continue;
    // initial beta and C from a straight line in log-log at this k
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const double lx = std::log(w[i] - k0), ly = std::log(Q[i]);
      sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    const double n = static_cast<double>(w.size());
    const double beta0 = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double logC0 = (sy - beta0 * sx) / n;
    Solution s = solve(pr, {logC0, std::log(w_min - k0), beta0}, Q_err);
    if (s.ok && s.chi2 < best.chi2) best = s;
  }
  if (!best.ok) throw FitError("Beverloo fit: the solver did not converge from any start");
  BeverlooFit f;
  f.C = std::exp(best.x[0]);
  f.k = w_min - std::exp(best.x[1]);
  f.beta = best.x[2];
  // standard errors by the delta method through the transformation
  f.C_err = f.C * std::sqrt(best.cov[0]);
  f.k_err = std::exp(best.x[1]) * std::sqrt(best.cov[4]);
  f.beta_err = std::sqrt(best.cov[8]);
  f.chi2_red = w.size() > 3 ? best.chi2 / (w.size() - 3) : 0;
  set_widths(f, w);
  return f;
}

namespace {

void check_lambdas(const std::vector<double>& lambda) {
  for (double l : lambda)
    if (!(l > 0) || !std::isfinite(l)) throw FitError("crossover fit: lambda must be finite and > 0 (the limits are not fitted)");
}

/// A crossover solve from a grid of starts in (log10 lambda_c, log b), the further parameters
/// starting at `rest`; the best by chi^2.
Solution solve_crossover(Problem& pr, const std::vector<double>& lambda, const std::vector<double>& rest,
                         const std::vector<double>& err, const std::string& what) {
  const double lo = std::log10(*std::min_element(lambda.begin(), lambda.end()));
  const double hi = std::log10(*std::max_element(lambda.begin(), lambda.end()));
  Solution best;
  for (double frac : {0.5, 0.25, 0.75})
    for (double b0 : {0.5, 1.0, 2.0}) {
      std::vector<double> x0 = {lo + frac * (hi - lo), std::log(b0)};
      x0.insert(x0.end(), rest.begin(), rest.end());
      Solution s = solve(pr, x0, err);
      if (s.ok && s.chi2 < best.chi2) best = s;
    }
  if (!best.ok) throw FitError(what + ": the solver did not converge from any start");
  return best;
}

/// lambda_c and b with their errors (the first two parameters), and chi^2 per degree of freedom.
CrossoverFit crossover_result(const Solution& best, std::size_t points) {
  const std::size_t p = best.x.size();
  CrossoverFit f;
  f.points = static_cast<int>(points);
  f.log10_lambda_c = best.x[0];
  f.log10_lambda_c_err = std::sqrt(best.cov[0]);
  f.lambda_c = std::pow(10.0, best.x[0]);
  f.lambda_c_err = f.lambda_c * std::log(10.0) * f.log10_lambda_c_err;
  f.b = std::exp(best.x[1]);
  f.b_err = f.b * std::sqrt(best.cov[p + 1]);
  f.chi2_red = points > p ? best.chi2 / static_cast<double>(points - p) : 0;
  return f;
}

}  // namespace

CrossoverFit fit_crossover(int d, const std::vector<double>& lambda, const std::vector<double>& beta,
                           const std::vector<double>& beta_err) {
  check_inputs("crossover fit", lambda, beta, beta_err, 3);
  check_lambdas(lambda);
  // Parameters (log10 lambda_c, log b): b > 0.
  Problem pr{lambda.size(), 2, [&](std::size_t i, const double* x) {
               return d - 1 - 0.5 * std::tanh((std::log10(lambda[i]) - x[0]) / std::exp(x[1]));
             }, &beta};
  CrossoverFit f = crossover_result(solve_crossover(pr, lambda, {}, beta_err, "crossover fit"), lambda.size());
  f.beta_0 = d - 0.5;
  f.beta_inf = d - 1.5;
  return f;
}

CrossoverFit fit_crossover_free_plateaus(const std::vector<double>& lambda, const std::vector<double>& beta,
                                         const std::vector<double>& beta_err) {
  check_inputs("crossover fit (plateaus free)", lambda, beta, beta_err, 5);
  check_lambdas(lambda);
  // Parameters (log10 lambda_c, log b, beta_0, beta_inf).
  Problem pr{lambda.size(), 4, [&](std::size_t i, const double* x) {
               return x[3] + (x[2] - x[3]) * 0.5 * (1 - std::tanh((std::log10(lambda[i]) - x[0]) / std::exp(x[1])));
             }, &beta};
  const double b_max = *std::max_element(beta.begin(), beta.end()), b_min = *std::min_element(beta.begin(), beta.end());
  const Solution best = solve_crossover(pr, lambda, {b_max, b_min}, beta_err, "crossover fit (plateaus free)");
  CrossoverFit f = crossover_result(best, lambda.size());
  f.plateaus_free = true;
  f.beta_0 = best.x[2];
  f.beta_0_err = std::sqrt(best.cov[10]);
  f.beta_inf = best.x[3];
  f.beta_inf_err = std::sqrt(best.cov[15]);
  return f;
}

BeverlooFit fit_beverloo_fixed_beta(const std::vector<double>& w_all, const std::vector<double>& Q_all, double beta,
                                    const BoundedFitOptions& o) {
  std::vector<double> w, Q;
  for (std::size_t i = 0; i < w_all.size() && i < Q_all.size(); ++i)
    if (w_all[i] > o.w_lo && w_all[i] < o.w_hi && std::isfinite(Q_all[i]) && Q_all[i] > 0.01 * kAuthorsFlowUnit) {
      w.push_back(w_all[i]);
      Q.push_back(Q_all[i]);
    }
  const std::vector<double> unit(w.size(), 1.0);
  check_inputs("Beverloo fit with beta fixed", w, Q, unit, 3);
  // Parameters (k, C), free, as in the authors' fit: |C| |w - k|^beta
  Problem pr{w.size(), 2, [&](std::size_t i, const double* x) { return std::fabs(x[1] * std::pow(std::fabs(w[i] - x[0]), beta)); },
             &Q};
  Solution best;
  const double w_min = *std::min_element(w.begin(), w.end());
  for (double k0 : {0.01, 1.0, 2.0, w_min - 0.5})
    for (double C0 : {0.01 * kAuthorsFlowUnit, 1.0, 5.0}) {
      Solution s = solve(pr, {k0, C0}, unit);
      if (s.ok && s.chi2 < best.chi2) best = s;
    }
  if (!best.ok) throw FitError("Beverloo fit with beta fixed: the solver did not converge from any start");
  BeverlooFit f;
  const double dof = w.size() > 2 ? static_cast<double>(w.size() - 2) : 1.0, s2 = best.chi2 / dof;
  f.k = best.x[0];
  f.k_err = std::sqrt(s2 * best.cov[0]);
  f.C = std::fabs(best.x[1]);
  f.C_err = std::sqrt(s2 * best.cov[3]);
  f.beta = beta;
  f.chi2_red = s2;
  set_widths(f, w);
  return f;
}

BoundedBeverlooFit fit_beverloo_bounded(const std::vector<double>& w_all, const std::vector<double>& Q_all,
                                        const BoundedFitOptions& o) {
  std::vector<double> w, Q;
  for (std::size_t i = 0; i < w_all.size() && i < Q_all.size(); ++i)
    if (w_all[i] > o.w_lo && w_all[i] < o.w_hi && std::isfinite(Q_all[i])) {
      w.push_back(w_all[i]);
      Q.push_back(Q_all[i]);
    }
  const std::vector<double> unit(w.size(), 1.0);  // unweighted, as MATLAB's fit without weights
  check_inputs("bounded Beverloo fit", w, Q, unit, 4);
  // Each parameter through p = lo + (hi - lo)(1 + sin u)/2 (MINUIT's transformation): any u is
  // inside the bounds, and a bound is reached exactly where the optimum lies beyond it.
  const double lo[3] = {o.C_lo, o.k_lo, o.beta_lo}, hi[3] = {o.C_hi, o.k_hi, o.beta_hi};
  auto param = [&](int j, double u) { return lo[j] + (hi[j] - lo[j]) * 0.5 * (1 + std::sin(u)); };
  auto inverse = [&](int j, double p) {
    const double t = std::clamp(2 * (p - lo[j]) / (hi[j] - lo[j]) - 1, -1.0, 1.0);
    return std::asin(t);
  };
  Problem pr{w.size(), 3, [&](std::size_t i, const double* x) {
               return std::fabs(param(0, x[0]) * std::pow(std::fabs(w[i] - param(1, x[1])), param(2, x[2])));
             }, &Q};
  Solution best;
  // the authors start from k = 2, C = 0.01 of their unit and beta = 1.5 - i/16 for their i-th
  // series; several starts here, the best kept (a bounded least-squares optimum does not depend on them)
  for (double beta0 : {0.5, 1.0, 1.5})
    for (double k0 : {1.0, 2.0, 3.5}) {
      Solution s = solve(pr, {inverse(0, 0.01 * kAuthorsFlowUnit), inverse(1, k0), inverse(2, beta0)}, unit);
      if (s.ok && s.chi2 < best.chi2) best = s;
    }
  if (!best.ok) throw FitError("bounded Beverloo fit: the solver did not converge from any start");
  BoundedBeverlooFit out;
  BeverlooFit& f = out.fit;
  const double dof = w.size() > 3 ? static_cast<double>(w.size() - 3) : 1.0;
  const double s2 = best.chi2 / dof;  // residual variance: the unweighted fit's error scale
  double value[3], err[3];
  bool at[3];
  for (int j = 0; j < 3; ++j) {
    value[j] = param(j, best.x[j]);
    err[j] = (hi[j] - lo[j]) * 0.5 * std::fabs(std::cos(best.x[j])) * std::sqrt(s2 * best.cov[4 * j]);
    at[j] = std::fabs(std::cos(best.x[j])) < 1e-3;  // within ~5e-7 of the range of a bound
  }
  f.C = value[0], f.C_err = err[0], f.k = value[1], f.k_err = err[1], f.beta = value[2], f.beta_err = err[2];
  f.chi2_red = s2;  // unweighted: the mean squared residual per degree of freedom, in Q's units squared
  out.C_at_bound = at[0], out.k_at_bound = at[1], out.beta_at_bound = at[2];
  set_widths(f, w);
  return out;
}

}  // namespace beverloo
