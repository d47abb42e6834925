#include "next_width.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace beverloo {

namespace {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// dQ/d(C, k, beta) of Q = C (w - k)^beta at w > k.
Vec3 gradient(const BeverlooFit& f, double w) {
  const double x = w - f.k, p = std::pow(x, f.beta);
  return Vec3(p, -f.C * f.beta * p / x, f.C * p * std::log(x));
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

DesignAdvice next_width(const BeverlooFit& fit, const std::vector<double>& w, const std::vector<double>& Q,
                        const std::vector<double>& Q_err, double w_lo, double w_hi, double step,
                        const DesignTargets& targets, const FlowTimeCosts* costs) {
  if (w.size() != Q.size() || w.size() != Q_err.size() || w.size() < 3)
    throw FitError("the design needs the fit's points (at least 3, each with w, Q and Q_err)");
  if (!(step > 0) || !(w_hi >= w_lo)) throw FitError("the candidate widths need w_lo <= w_hi and a step > 0");
  Mat3 F = Mat3::Zero();
  std::vector<double> rel, flow;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(Q[i] > 0 && Q_err[i] > 0) || !(w[i] > fit.k)) continue;
    const Vec3 g = gradient(fit, w[i]);
    F += g * g.transpose() / (Q_err[i] * Q_err[i]);
    rel.push_back(Q_err[i] / Q[i]);
    flow.push_back(Q[i]);
  }
  if (rel.size() < 3) throw FitError("fewer than 3 flowing points above k");
  const Eigen::FullPivLU<Mat3> lu(F);
  if (!lu.isInvertible()) throw FitError("the points do not determine C, k and beta (singular information)");
  const Mat3 cov = lu.inverse();
  DesignAdvice a;
  a.k_err_now = std::sqrt(cov(1, 1));
  a.beta_err_now = std::sqrt(cov(2, 2));
  const bool any_target = targets.k_err || targets.beta_err;
  a.targets_met = any_target && (!targets.k_err || a.k_err_now <= *targets.k_err) &&
                  (!targets.beta_err || a.beta_err_now <= *targets.beta_err);
  if (a.targets_met) return a;
  // the weights of phi: the targets given, else the present variances (relative reduction)
  const double s_k = targets.k_err ? *targets.k_err : (any_target ? INFINITY : a.k_err_now);
  const double s_b = targets.beta_err ? *targets.beta_err : (any_target ? INFINITY : a.beta_err_now);
  auto phi = [&](const Mat3& c) { return c(1, 1) / (s_k * s_k) + c(2, 2) / (s_b * s_b); };
  const double phi_now = phi(cov), r = median(rel), q_ref = median(flow);
  // the cost of a new run at flow rate q: relative to a run at the median Q, or in t0 of flow
  auto new_run_cost = [&](double q) {
    return costs ? costs->start_t0 + costs->exits_rel2 / (r * r * q) : q_ref / q;
  };
  const double reference_cost = new_run_cost(q_ref);
  double best_score = -INFINITY;
  const int count = static_cast<int>(std::floor((w_hi - w_lo) / step + 1e-9)) + 1;
  for (int n = 0; n < count; ++n) {
    const double wc = w_lo + n * step;  // from the index, not a running sum: the same grid every time
    if (wc <= fit.k + step) continue;
    const double q = fit.C * std::pow(wc - fit.k, fit.beta);
    if (!(q > 0) || !std::isfinite(q)) continue;
    const Vec3 g = gradient(fit, wc);
    const double sigma = r * q;
    const Eigen::FullPivLU<Mat3> after_lu(F + g * g.transpose() / (sigma * sigma));
    if (!after_lu.isInvertible()) continue;
    const Mat3 after = after_lu.inverse();
    const double cost = new_run_cost(q);
    const double score = (phi_now - phi(after)) / cost;
    if (score > best_score) {  // strict: ties go to the smaller w
      best_score = score;
      a.next = NextWidth{wc, std::sqrt(after(1, 1)), std::sqrt(after(2, 2)), cost / reference_cost, std::nullopt};
    }
  }
  if (costs) {
    for (std::size_t i = 0; i < costs->runs.size(); ++i) {
      const FlowTimeCosts::Run& run = costs->runs[i];
      if (!(run.w > fit.k && run.Q_err > 0 && run.window_t0 > 0)) continue;
      const Vec3 g = gradient(fit, run.w);
      const Eigen::FullPivLU<Mat3> after_lu(F + g * g.transpose() / (run.Q_err * run.Q_err));
      if (!after_lu.isInvertible()) continue;
      const Mat3 after = after_lu.inverse();
      const double score = (phi_now - phi(after)) / run.window_t0;
      // a tie (to rounding: the same information for the same flow when a new run's start is
      // free) goes to the new run, whose seed adds to the run-to-run spread; among runs, the first
      if (score > best_score + 1e-9 * std::abs(best_score)) {
        best_score = score;
        a.next = NextWidth{run.w, std::sqrt(after(1, 1)), std::sqrt(after(2, 2)), run.window_t0 / reference_cost, i};
      }
    }
  }
  if (!a.next) throw FitError("no candidate width above k + step in the range given");
  return a;
}

}  // namespace beverloo
