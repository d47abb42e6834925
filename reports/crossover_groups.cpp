#include "crossover_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/digest.h"
#include "engine/parameters.h"
#include "reports/number_format.h"
#include "series_fits.h"
#include "series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;
std::string fmt(double v, int digits = 4) { return table_number(v, digits); }

/// " theta=60/60" for a hopper that is not flat-bottomed, as in the series' labels: the groups
/// of Fig. 6 differ only in it, and label disambiguation cannot see it (the base jobs it
/// compares are angle-free).
std::string angle_text(const Series& s) {
  return s.theta_left != 90 || s.theta_right != 90 ? " theta=" + fmt(s.theta_left) + "/" + fmt(s.theta_right) : "";
}

/// The crossover's run-to-run spread (Crossover::spread): each replica that has its own free
/// fit in every finite-lambda series with two or more replica fits is fitted alone, both ways,
/// over those lambdas. A lambda with fewer than two replica fits (a costly one run once, or one
/// whose seeds blew up at different widths) is left out of the replicas' fits and counted,
/// rather than taking the spread of the whole group with it.
void replica_spread(Crossover& g, const std::vector<const Series*>& fitted, const std::vector<double>& lambda) {
  std::vector<const Series*> replicated;
  std::vector<double> replicated_lambda;
  for (std::size_t i = 0; i < fitted.size(); ++i)
    if (fitted[i]->replica_fit.size() >= 2) {
      replicated.push_back(fitted[i]);
      replicated_lambda.push_back(lambda[i]);
    }
  // the paper's form has three parameters: fewer lambdas than that fix nothing
  if (replicated.size() < 3) return;
  std::set<int> replicas;
  for (const auto& [replica, fit] : replicated.front()->replica_fit) replicas.insert(replica);
  for (const Series* s : replicated)
    for (auto it = replicas.begin(); it != replicas.end();)
      it = s->replica_fit.count(*it) ? std::next(it) : replicas.erase(it);
  if (replicas.size() < 2) return;
  const int left_out = static_cast<int>(fitted.size() - replicated.size());
  std::vector<double> log_lc, b, log_lc_free, b_free;
  for (int replica : replicas) {
    std::vector<double> beta, beta_err;
    for (const Series* s : replicated) {
      beta.push_back(s->replica_fit.at(replica).beta);
      beta_err.push_back(s->replica_fit.at(replica).beta_err);
    }
    try {
      const CrossoverFit f = fit_crossover(g.dimension, replicated_lambda, beta, beta_err);
      log_lc.push_back(f.log10_lambda_c);
      b.push_back(f.b);
    } catch (const FitError&) {
    }
    try {
      const CrossoverFit f = fit_crossover_free_plateaus(replicated_lambda, beta, beta_err);
      log_lc_free.push_back(f.log10_lambda_c);
      b_free.push_back(f.b);
    } catch (const FitError&) {
    }
  }
  g.spread = {static_cast<int>(log_lc.size()), sample_sd(log_lc), sample_sd(b), left_out};
  g.spread_free = {static_cast<int>(log_lc_free.size()), sample_sd(log_lc_free), sample_sd(b_free), left_out};
}

/// A crossover fit whose covariance is singular (b's or lambda_c's error 0, or not finite) is
/// not a measurement: a step too sharp for the lambdas (b -> 0) puts lambda_c wherever the one
/// point on the step is matched, with an error that says nothing. Nor is one whose covariance is
/// nearly singular: the free-plateau sigmoid on a step with no point inside it came out with
/// lambda_c 0.031 +- 1e12 (the DP Fig. 6a campaign at 30 deg), finite but beyond any lambda a
/// campaign holds. Such a fit is dropped with a message saying why (and kept in `singular`, when
/// given, for the adaptive planner); the group is then read at each lambda (Fig. 6a at one
/// lambda).
void drop_if_degenerate(std::optional<CrossoverFit>& fit, std::string& message,
                        std::optional<CrossoverFit>* singular = nullptr) {
  if (!fit) return;
  // beyond these the fit says nothing: lambda_c anywhere in six decades, b unknown 100 times over
  constexpr double kMaxLog10LambdaCErr = 3.0, kMaxRelativeBErr = 100.0;
  const bool determined = fit->b_err > 0 && std::isfinite(fit->b_err) && fit->log10_lambda_c_err > 0 &&
                          std::isfinite(fit->log10_lambda_c_err) && fit->log10_lambda_c_err < kMaxLog10LambdaCErr &&
                          fit->b_err < kMaxRelativeBErr * std::fabs(fit->b);
  if (determined) return;
  char b[200];
  std::snprintf(b, sizeof b,
                "not determined: a singular fit (lambda_c %.3g, b %.3g with no usable error): the lambdas do not "
                "resolve the step's width",
                fit->lambda_c, fit->b);
  message = b;
  if (singular) *singular = fit;
  fit.reset();
}

/// The lambda, beta and beta's error of each series, for the crossover fits.
struct Exponents {
  std::vector<double> lambda, beta, beta_err;
};
Exponents exponents_of(const std::vector<const Series*>& series) {
  Exponents x;
  for (const Series* s : series) {
    x.lambda.push_back(s->lambda);
    x.beta.push_back(s->fit->beta);
    x.beta_err.push_back(s->fit->beta_err);
  }
  return x;
}

/// Sorts a crossover group's finite-lambda series and fits the sigmoid to the beta of those
/// that follow a Beverloo law (the others are set apart in no_beverloo_law, and a fit that fails
/// for want of them says so).
void fit_group(Crossover& g) {
  std::sort(g.finite.begin(), g.finite.end(), [](const Series* a, const Series* b) { return a->lambda < b->lambda; });
  std::vector<const Series*> fitted;
  for (const Series* s : g.finite) (follows_no_beverloo_law(*s) ? g.no_beverloo_law : fitted).push_back(s);
  const Exponents x = exponents_of(fitted);
  const std::vector<double>&l = x.lambda, &b = x.beta, &e = x.beta_err;
  std::string left_out;
  for (const Series* s : g.no_beverloo_law) left_out += (left_out.empty() ? "" : ", ") + fmt(s->lambda, 3);
  if (!left_out.empty()) left_out = " (left out, " + no_beverloo_law_rule() + ": no Beverloo law at lambda = " + left_out + ")";
  try {
    g.fit = fit_crossover(g.dimension, l, b, e);
  } catch (const FitError& err) {
    g.message = err.what() + left_out;
  }
  try {
    g.fit_free = fit_crossover_free_plateaus(l, b, e);
  } catch (const FitError& err) {
    g.message_free = err.what() + left_out;
  }
  drop_if_degenerate(g.fit, g.message, &g.design_fit);
  drop_if_degenerate(g.fit_free, g.message_free);
  if (!g.fit && !g.design_fit && !g.no_beverloo_law.empty()) {
    const Exponents all = exponents_of(g.finite);
    try {
      g.design_fit = fit_crossover(g.dimension, all.lambda, all.beta, all.beta_err);
    } catch (const FitError&) {  // no design either: the planner stops the group, saying why
    }
  }
  replica_spread(g, fitted, l);
}
}  // namespace

std::vector<Crossover> crossover_groups(const std::vector<Series>& series, const std::map<std::string, json>& base_job_of) {
  std::vector<Crossover> out;
  // crossover groups: series sharing everything but zeta/mu, with the same drag for finite lambda
  std::map<std::string, Crossover> groups;
  for (const Series& s : series) {
    if (!(s.zeta > 0) || s.drag_rate > 0 || s.drain) continue;  // lambda = 0 joins below as a limit
    std::string gkey = s.base_key + "|zeta=" + fmt(s.zeta, 12);
    if (s.mu_n) gkey += "|mu_n=" + fmt(*s.mu_n, 12);  // (absent for the text's model: keys as before)
    if (s.mu_t) gkey += "|mu_t=" + fmt(*s.mu_t, 12);
    Crossover& g = groups[gkey];
    g.key = sha256_hex(gkey);
    g.angle_family = sha256_hex(s.angle_free_key + gkey.substr(gkey.find('|')));
    g.dimension = s.dimension;
    g.label = std::to_string(s.dimension) + "D " + s.stiffness + " zeta=" + fmt(s.zeta, 3) + angle_text(s) + " N=" +
              std::to_string(s.N);
    if (std::isinf(s.lambda))
      g.limit_inf = &s;
    else if (s.fit)
      g.finite.push_back(&s);
    else {
      g.unfitted_lambda.push_back(s.lambda);
      g.unfitted.push_back(&s);
    }
  }
  for (auto& [gkey, g] : groups) {
    const std::string zeta_part = gkey.substr(gkey.find("|zeta=") + 6);
    const double scale = derived::axis_scale_of_zeta(std::stod(zeta_part.substr(0, zeta_part.find('|'))));
    for (const Series& s : series)  // lambda = 0 at the same dissipation scale
      if (s.zeta == 0 && s.base_key == gkey.substr(0, gkey.find('|')) &&
          std::fabs(derived::axis_scale_of_friction_limit(s.mu) - scale) <= 1e-9 * scale)
        g.limit0 = &s;
    fit_group(g);
    out.push_back(g);
  }
  // The authors' lambda axis (docs/authors-model.md): drag as a rate times the mass, and
  // lambda = drag_rate M(sigma_avg) / mu_t. Their Fig. 4 varies it along two branches, the drag
  // at a fixed friction and then the friction at a fixed drag (Matlab-process oop/paper.m, bVec
  // and vVec), and plots both as one beta(lambda): so a group is every rate-drag series with
  // friction sharing everything else (the form of the friction, mu_n, included). Its limits:
  // lambda = 0, the friction of its lowest-lambda series without drag; lambda = inf, the drag of
  // its highest-lambda series without friction (else any rate-drag series without friction).
  std::map<std::string, Crossover> by_rate_drag;
  for (const Series& s : series) {
    if (!(s.drag_rate > 0) || s.zeta != 0 || !(s.mu > 0) || s.drain) continue;
    const std::string gkey = s.base_key + "|rate_drag|mu_n=" + (s.mu_n ? fmt(*s.mu_n, 12) : "mu");
    Crossover& g = by_rate_drag[gkey];
    g.key = sha256_hex(gkey);
    g.angle_family = sha256_hex(s.angle_free_key + gkey.substr(gkey.find('|')));
    g.dimension = s.dimension;
    if (s.fit) {
      g.finite.push_back(&s);
    } else {
      g.unfitted_lambda.push_back(s.lambda);
      g.unfitted.push_back(&s);
    }
  }
  for (auto& [gkey, g] : by_rate_drag) {
    const std::string base = gkey.substr(0, gkey.find('|'));
    const Series* lowest = nullptr;
    const Series* highest = nullptr;
    for (const Series* s : g.finite) {
      if (!lowest || s->lambda < lowest->lambda) lowest = s;
      if (!highest || s->lambda > highest->lambda) highest = s;
    }
    std::set<double> frictions, drags;  // of every finite-lambda series, fitted or not
    for (const auto* list : {&g.finite, &g.unfitted})
      for (const Series* s : *list) {
        frictions.insert(s->mu);
        drags.insert(s->drag_rate);
      }
    const Series* any_inf = nullptr;
    for (const Series& s : series) {
      if (s.base_key != base || s.drain) continue;
      if (lowest && s.zeta == 0 && s.drag_rate == 0 && s.mu == lowest->mu && s.mu_n == lowest->mu_n &&
          s.mu_t == lowest->mu_t)
        g.limit0 = &s;
      if (s.mu == 0 && s.zeta == 0 && s.drag_rate > 0) {
        if (highest && s.drag_rate == highest->drag_rate) g.limit_inf = &s;
        if (!any_inf) any_inf = &s;
      }
    }
    if (!g.limit_inf) g.limit_inf = any_inf;
    // a group without a fitted series is still named after its series (Fig. 6b reads its ratio)
    const Series* any = lowest ? lowest : !g.unfitted.empty() ? g.unfitted.front() : g.limit0;
    g.label = std::to_string(any ? any->dimension : g.dimension) + "D " + (any ? any->stiffness : std::string()) +
              (frictions.size() == 1   ? " mu=" + fmt(*frictions.begin(), 4) + " (drag rate)"
               : drags.size() == 1     ? " drag_rate=" + fmt(*drags.begin(), 4) + " (mu varied)"
                                       : std::string(" (drag rate and mu varied)")) +
              (any ? angle_text(*any) + " N=" + std::to_string(any->N) : std::string());
    fit_group(g);
    out.push_back(g);
  }
  // groups that differ in something other than their label's fields say so, as series do
  std::vector<std::string> labels;
  std::vector<json> bases;
  for (const Crossover& g : out) {
    const Series* any = !g.finite.empty() ? g.finite.front() : g.limit0 ? g.limit0 : g.limit_inf;
    labels.push_back(g.label);
    bases.push_back(any ? base_job_of.at(any->key) : json::object());
  }
  disambiguate_labels(labels, bases);
  for (std::size_t i = 0; i < labels.size(); ++i) out[i].label = labels[i];
  return out;
}

double log10_lambda_c_sigma(const CrossoverFit& fit, const Crossover::ReplicaSpread& spread) {
  return std::isnan(spread.log10_lambda_c) ? fit.log10_lambda_c_err
                                           : std::max(fit.log10_lambda_c_err, spread.log10_lambda_c);
}

double chi2_scale(const CrossoverFit& fit) { return chi2_error_scale(fit.chi2_red); }

double log10_lambda_c_sigma_chi2_scaled(const CrossoverFit& fit, const Crossover::ReplicaSpread& spread) {
  CrossoverFit scaled = fit;
  scaled.log10_lambda_c_err *= chi2_scale(fit);
  return log10_lambda_c_sigma(scaled, spread);
}

std::optional<ForceRatioAtLambda> force_ratio_at_paper_lambda(const Crossover& g) {
  // how far (in decades) each of two bracketing series may lie, and the nearest without a bracket
  constexpr double kBracketDecades = 1.0, kNearestDecades = 0.5;
  auto decades = [](double lambda) { return std::log10(lambda / kForceRatioLambda); };
  std::vector<const Series*> below, above;  // series with a ratio on each side of the lambda
  for (const auto* list : {&g.finite, &g.unfitted})
    for (const Series* s : *list) {
      const double off = decades(s->lambda);
      if (std::fabs(off) > kBracketDecades || s->force_ratio.runs == 0) continue;
      (off <= 0 ? below : above).push_back(s);
    }
  auto closest = [&](const std::vector<const Series*>& side) {
    return *std::min_element(side.begin(), side.end(), [&](const Series* a, const Series* b) {
      return std::fabs(decades(a->lambda)) < std::fabs(decades(b->lambda));
    });
  };
  auto as_read = [](const Series& s) {
    ForceRatioAtLambda out;
    out.lambda = out.lambda_below = out.lambda_above = s.lambda;
    out.mean = s.force_ratio.mean, out.err = s.force_ratio.err, out.runs = s.force_ratio.runs;
    out.series = &s;
    return out;
  };
  if (!below.empty() && !above.empty()) {
    const Series &lo = *closest(below), &hi = *closest(above);
    for (const Series* at : {&lo, &hi})
      if (std::fabs(decades(at->lambda)) < 1e-6) return as_read(*at);  // a series at the lambda itself
    ForceRatioAtLambda out;
    out.lambda = kForceRatioLambda;
    out.lambda_below = lo.lambda;
    out.lambda_above = hi.lambda;
    out.runs = lo.force_ratio.runs + hi.force_ratio.runs;
    const double t = -decades(lo.lambda) / (decades(hi.lambda) - decades(lo.lambda));
    out.mean = std::exp((1 - t) * std::log(lo.force_ratio.mean) + t * std::log(hi.force_ratio.mean));
    out.err = out.mean * std::hypot((1 - t) * lo.force_ratio.err / lo.force_ratio.mean,
                                    t * hi.force_ratio.err / hi.force_ratio.mean);
    return out;
  }
  const std::vector<const Series*>& side = below.empty() ? above : below;
  if (side.empty()) return std::nullopt;
  const Series& nearest = *closest(side);
  if (std::fabs(decades(nearest.lambda)) > kNearestDecades) return std::nullopt;
  return as_read(nearest);
}

std::string lambda_c_spread_phrase(const Crossover::ReplicaSpread& spread) {
  return std::isnan(spread.log10_lambda_c) ? std::string()
                                           : "spread " + format_value(spread.log10_lambda_c, 2) + " in log10 over " +
                                                 std::to_string(spread.replicas) + " replicas" +
                                                 (spread.lambdas_left_out == 0
                                                      ? std::string()
                                                      : ", leaving out " + std::to_string(spread.lambdas_left_out) +
                                                            (spread.lambdas_left_out == 1 ? " lambda" : " lambdas") +
                                                            " with fewer than two replica fits");
}

std::optional<double> paper_lambda_c_at_angle(int dimension, double theta_w_deg) {
  if (dimension != 2) return std::nullopt;
  if (theta_w_deg == 90) return 5e-2;
  if (theta_w_deg == 20) return 6e-3;
  if (theta_w_deg == 30) return 5e-3;
  return std::nullopt;
}

std::pair<double, double> paper_beta_interval(int dimension, double lambda, double lambda_c) {
  const double mid = dimension - 1.0, edge = mid - std::tanh(std::log10(lambda / lambda_c)) / 2;
  return {std::min(mid, edge), std::max(mid, edge)};
}

std::map<std::string, std::map<double, const Crossover*>> angle_families(const std::vector<Crossover>& crossovers,
                                                                         bool fitted_only) {
  std::map<std::string, std::map<double, const Crossover*>> families;
  for (const Crossover& g : crossovers) {
    if (fitted_only && !g.fit && !g.fit_free) continue;
    const Series* any = !g.finite.empty() ? g.finite.front() : !g.unfitted.empty() ? g.unfitted.front() : nullptr;
    if (!any) continue;  // limits only: no angle of its own to be read at
    const Series& s = *any;
    if (s.theta_left == s.theta_right) families[g.angle_family].emplace(s.theta_left, &g);
  }
  return families;
}

namespace {

/// Where the parabola through (x[0], b[0]), (x[1], b[1]), (x[2], b[2]) takes `level` between
/// lo and hi, where it changes sign (it is the data there). Bisection: a closed form would lose
/// its digits when the parabola is nearly a line, the usual case.
double parabola_crossing(const double (&x)[3], const double (&b)[3], double level, double lo, double hi) {
  auto p = [&](double t) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      double term = b[i];
      for (int j = 0; j < 3; ++j)
        if (j != i) term *= (t - x[j]) / (x[i] - x[j]);
      sum += term;
    }
    return sum - level;
  };
  double p_lo = p(lo);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double mid = 0.5 * (lo + hi), p_mid = p(mid);
    if ((p_mid > 0) == (p_lo > 0)) lo = mid, p_lo = p_mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/// The crossing of `level` by the exponents `fit_of` gives (nullptr: the series is left out).
template <class FitOf>
std::optional<MidpointCrossing> crossing_of(const Crossover& g, double level, FitOf fit_of) {
  std::vector<std::pair<double, const BeverlooFit*>> points;  // (lambda, fit)
  for (const Series* s : g.finite)
    if (const BeverlooFit* f = fit_of(*s); f && s->lambda > 0) points.emplace_back(s->lambda, f);
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double b1 = points[i].second->beta, b2 = points[i + 1].second->beta;
    if ((b1 - level) * (b2 - level) > 0 || b1 == b2) continue;
    const double x1 = std::log10(points[i].first), x2 = std::log10(points[i + 1].first);
    const double f = (b1 - level) / (b1 - b2);
    const double d1 = (x2 - x1) * (level - b2) / ((b1 - b2) * (b1 - b2)), d2 = (x2 - x1) * (b1 - level) / ((b1 - b2) * (b1 - b2));
    MidpointCrossing m;
    m.log10_lambda = x1 + f * (x2 - x1);
    m.sigma = std::hypot(d1 * points[i].second->beta_err, d2 * points[i + 1].second->beta_err);
    m.lambda_lo = points[i].first, m.lambda_hi = points[i + 1].first;
    // the parabolas through the pair and the point below it, and the point above it
    std::vector<std::size_t> firsts;
    if (i >= 1) firsts.push_back(i - 1);
    if (i + 2 < points.size()) firsts.push_back(i);
    for (const std::size_t first : firsts) {
      double x[3], b[3];
      for (int j = 0; j < 3; ++j) x[j] = std::log10(points[first + j].first), b[j] = points[first + j].second->beta;
      const double moved = std::fabs(parabola_crossing(x, b, level, x1, x2) - m.log10_lambda);
      m.interpolation = std::isnan(m.interpolation) ? moved : std::max(m.interpolation, moved);
    }
    // a neighbour's step against the pair's direction: beta turns back there
    const double direction = b2 > b1 ? 1 : -1;
    auto against = [&](std::size_t from, std::size_t to) {
      const BeverlooFit &a = *points[from].second, &c = *points[to].second;
      const double step = (c.beta - a.beta) * direction, err = std::hypot(a.beta_err, c.beta_err);
      if (step < 0 && err > 0) m.reversal_z = std::isnan(m.reversal_z) ? -step / err : std::max(m.reversal_z, -step / err);
    };
    if (i >= 1) against(i - 1, i);
    if (i + 2 < points.size()) against(i + 1, i + 2);
    return m;
  }
  return std::nullopt;
}

}  // namespace

std::optional<MidpointCrossing> crossing_of_d_minus_1(const Crossover& g) {
  const double level = g.dimension - 1.0;
  std::optional<MidpointCrossing> pooled = crossing_of(g, level, [](const Series& s) -> const BeverlooFit* {
    return s.fit && fit_quality(s) == "ok" ? &*s.fit : nullptr;
  });
  if (!pooled) return pooled;
  std::set<int> replicas;
  for (const Series* s : g.finite)
    for (const auto& [replica, fit] : s->replica_fit) replicas.insert(replica);
  std::vector<double> own;
  for (const int replica : replicas) {
    const auto m = crossing_of(g, level, [replica](const Series& s) -> const BeverlooFit* {
      const auto it = s.replica_fit.find(replica);
      return it == s.replica_fit.end() ? nullptr : &it->second;
    });
    if (m) own.push_back(m->log10_lambda);
  }
  pooled->replicas = static_cast<int>(own.size());
  pooled->spread = sample_sd(own);
  return pooled;
}

}  // namespace beverloo
