#include "series_fits.h"

#include <cmath>
#include <map>
#include <tuple>

namespace beverloo {
namespace {

/// Replicas at each w pooled by inverse-variance weights; clogged ones counted, not pooled.
void pool_points(Series& s, const std::vector<RunRecord>& runs) {
  std::map<double, std::vector<const RunRecord*>> by_w;
  for (const RunRecord& r : runs) by_w[r.w].push_back(&r);
  for (const auto& [w, reps] : by_w) {
    SeriesPoint p;
    p.w = w;
    p.replicas = static_cast<int>(reps.size());
    double sw = 0, swq = 0;
    for (const RunRecord* r : reps) {
      p.time_limited += r->time_limited;
      if (r->clogged) {
        ++p.clogged;
        continue;
      }
      if (r->Q > 0 && r->Q_err > 0 && std::isfinite(r->Q) && std::isfinite(r->Q_err)) {
        sw += 1 / (r->Q_err * r->Q_err);
        swq += r->Q / (r->Q_err * r->Q_err);
      } else {
        ++s.left_out;  // a rate without an error cannot be weighted: not a 0 +- 0 point
      }
    }
    if (sw > 0) {
      p.Q = swq / sw;
      p.Q_err = 1 / std::sqrt(sw);
    }
    if (sw > 0 || p.clogged > 0) s.points.push_back(p);
  }
}

/// The run-to-run spread: each replica (seed) fitted alone where it has every width the pooled
/// fit used; the sample standard deviation of their betas and ks, beside the fit's own error
/// (the pooled fit's error says how well one set of points fixes beta, not how far another
/// seed's set would move it). Likewise k of the authors' fits with beta held, over the replicas
/// where that fit exists.
void replica_spread(Series& s, const std::vector<RunRecord>& runs, std::size_t widths) {
  std::map<int, std::map<double, const RunRecord*>> by_replica;
  for (const RunRecord& r : runs)
    if (!r.clogged && r.Q > 0 && r.Q_err > 0) by_replica[r.replica][r.w] = &r;
  std::vector<double> betas, ks, ks_lo, ks_hi, log_Cs_lo, log_Cs_hi;
  for (const auto& [replica, pts] : by_replica) {
    if (pts.size() != widths) continue;
    std::vector<double> rw, rq, re;
    for (const auto& [w, r] : pts) {
      rw.push_back(w);
      rq.push_back(r->Q);
      re.push_back(r->Q_err);
    }
    try {
      const BeverlooFit f = fit_beverloo(rw, rq, re);
      betas.push_back(f.beta);
      ks.push_back(f.k);
      s.replica_fit[replica] = f;
    } catch (const FitError&) {
    }
    if (s.rate_is_c0()) continue;  // no authors' fits of a drain's c0 t0
    for (auto [beta, out, log_C] :
         {std::tuple{s.dimension - 1.5, &ks_lo, &log_Cs_lo}, std::tuple{s.dimension - 0.5, &ks_hi, &log_Cs_hi}}) {
      try {
        const BeverlooFit held = fit_beverloo_fixed_beta(rw, rq, beta, BoundedFitOptions::authors());
        out->push_back(held.k);
        if (held.C > 0) log_C->push_back(std::log(held.C));
      } catch (const FitError&) {
      }
    }
  }
  s.replica_fits = static_cast<int>(betas.size());
  s.beta_replica_spread = sample_sd(betas);
  s.k_replica_spread = sample_sd(ks);
  s.k_at_beta_lo_replica_spread = sample_sd(ks_lo);
  s.k_at_beta_hi_replica_spread = sample_sd(ks_hi);
  s.log_C_at_beta_lo_replica_spread = sample_sd(log_Cs_lo);
  s.log_C_at_beta_hi_replica_spread = sample_sd(log_Cs_hi);
}

/// Per w, Kaplan-Meier over the replicas, for every w of a series in which some run clogged.
void clog_statistics(Series& s, const std::vector<RunRecord>& runs) {
  std::map<double, std::vector<SurvivalObservation>> by_w;
  std::map<double, double> t_max;
  bool any_clog = false;
  for (const RunRecord& r : runs) {
    by_w[r.w].push_back({r.clogged && r.clog_time >= 0 ? r.clog_time : r.end_time, r.clogged});
    t_max[r.w] = r.t_max;
    any_clog = any_clog || r.clogged;
  }
  if (!any_clog) return;
  for (const auto& [w, obs] : by_w) s.clog_points.push_back({w, t_max[w], kaplan_meier(obs)});
}

/// Series::force_ratio: the runs that ended flowing (a clogged run's window is its jam).
void force_ratio(Series& s, const std::vector<RunRecord>& runs) {
  std::vector<double> values, errors;
  std::map<double, std::vector<double>> by_w, err_by_w;
  for (const RunRecord& r : runs)
    if (!r.clogged && r.Q > 0 && std::isfinite(r.force_ratio) && r.force_ratio > 0) {
      values.push_back(r.force_ratio);
      errors.push_back(r.force_ratio_err);
      by_w[r.w].push_back(r.force_ratio);
      err_by_w[r.w].push_back(r.force_ratio_err);
    }
  for (const auto& [w, at] : by_w) s.force_ratio.by_w[w] = sample_mean(at);
  for (const auto& [w, errs] : err_by_w) {
    double sum2 = 0;
    for (double e : errs) sum2 += e * e;
    if (std::isfinite(sum2) && sum2 > 0) s.force_ratio.by_w_err[w] = std::sqrt(sum2) / errs.size();
  }
  s.force_ratio.runs = static_cast<int>(values.size());
  if (values.empty()) return;
  s.force_ratio.mean = sample_mean(values);
  // over two runs or more the scatter between them (widths included: the ratio grows with w);
  // one run has only its own error over time
  s.force_ratio.err = values.size() >= 2 ? sample_sd(values) / std::sqrt(values.size()) : errors.front();
}

}  // namespace

void fit_series(Series& s, const std::vector<RunRecord>& runs) {
  pool_points(s, runs);
  force_ratio(s, runs);
  std::vector<double> w, Q, e;
  s.flowing_columns(w, Q, e);
  try {
    s.fit = fit_beverloo(w, Q, e);
  } catch (const FitError& err) {
    s.message = err.what();
  }
  if (s.fit) replica_spread(s, runs, w.size());
  if (s.rate_is_c0()) return;  // a drain's c0 t0: no clog statistics, no authors' fit
  clog_statistics(s, runs);
  try {
    s.authors_fit = fit_beverloo_bounded(w, Q, BoundedFitOptions::authors());
  } catch (const FitError& err) {
    s.authors_message = err.what();
  }
  for (auto [beta, fit] : {std::pair{s.dimension - 1.5, &s.authors_fixed_lo}, std::pair{s.dimension - 0.5, &s.authors_fixed_hi}}) {
    try {
      *fit = fit_beverloo_fixed_beta(w, Q, beta, BoundedFitOptions::authors());
    } catch (const FitError&) {
      // too few points above the authors' flow threshold: NULL in the table
    }
  }
}

double sample_mean(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double mean = 0;
  for (double x : v) mean += x / v.size();
  return mean;
}

double sample_sd(const std::vector<double>& v) {
  if (v.size() < 2) return NAN;
  const double mean = sample_mean(v);
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / (v.size() - 1));
}

}  // namespace beverloo
