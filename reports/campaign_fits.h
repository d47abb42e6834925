#pragma once
/// \file campaign_fits.h
/// \brief From a campaign's results to its fits: series (every parameter but w equal, replicas
/// pooled by inverse-variance weighting, clogged points left out of the fit but reported), one
/// Beverloo fit per series, and one crossover fit per group of series that differ only in
/// lambda = zeta/mu (same other parameters and the same drag scale for finite lambda).
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/campaign/campaign_scope.h"
#include "orchestrator/db/database.h"
#include "reports/fit.h"
#include "reports/survival.h"

namespace beverloo {

struct SeriesPoint {
  double w = 0, Q = 0, Q_err = 0;
  int replicas = 0, clogged = 0;
  int time_limited = 0;  ///< replicas that stopped at run.t_max before reaching the target error
  bool flowing() const { return Q > 0 && Q_err > 0; }
};

/// |F_zeta| / |F_mu| (the paper's Fig. 6b) of a series: the mean over its runs that ended
/// flowing with a finite ratio (each run's ratio of its window's mean forces), and the standard
/// error of that mean over those runs; a series of one run has that run's own error (over the
/// time blocks of its window; NaN from an engine before the field).
struct ForceRatio {
  double mean = NAN, err = NAN;
  int runs = 0;
  /// per width, the mean over its runs: the ratio grows with w, so two angles are compared
  /// width by width where they share widths (paper_claims), not through the means' scatter
  std::map<double, double> by_w;
  /// per width, the standard error of by_w from its runs' own errors (sqrt(sum err^2) / n);
  /// absent where a run has none
  std::map<double, double> by_w_err;
};

struct Series {
  std::string key, label, base_key;  ///< base_key: without zeta and mu (finds the lambda limits)
  /// base_key without the hopper angles as well: the beta(lambda) groups that share it differ
  /// only in theta_w (the paper's Fig. 6)
  std::string angle_free_key;
  /// The series' job without N (dissipation kept): the series that share it differ only in the
  /// number of particles (the paper's Appendix C, Fig. C(b))
  std::string size_free_key;
  /// The series' job without E_sp (dissipation kept): SP series that share it differ only in
  /// their stiffness (the paper's Fig. 7a, and its "C nearly independent of softness")
  std::string stiffness_free_key;
  /// The series' job without the particle model and its own settings (model, E_sp,
  /// sp_contact_law, dp.*, the wall stiffness E_w) and without the numerics and run settings
  /// (run.*, dt, fire, max_overlap, skin, observables): SP and DP series that share it flow under
  /// the same conditions (N, W, angles, dissipation, reinjection), the paper's Appendix B pairs.
  std::string model_free_key;
  /// Replicas with a flow rate but no usable error (Q_err not > 0 or not a number): left out
  /// of the pooled points and the fit, and said so (never pooled as Q = 0 +- 0).
  int left_out = 0;
  /// Runs continued by a longer run of their own trajectory (run.min_time: more flow time for a
  /// point): left out, the longer run holds their flow (reports/campaign_runs.cpp).
  int continued = 0;
  std::string model = "sp";          ///< sp, dp_smooth, dp_rough; "experiment" for an imported series
  std::string stiffness;             ///< the model's stiffness parameters, e.g. "SP E_sp=100"
  int dimension = 2, N = 0;
  int n_v = 0;                       ///< DP only (0 for SP)
  double E_sp = NAN;                 ///< SP only (NaN for DP)
  double K_a = NAN, K_l = NAN, K_b = NAN, E_c = NAN;  ///< DP only (NaN for SP)
  double zeta = 0, mu = 0, lambda = 0, theta_left = 90, theta_right = 90;
  double drag_rate = 0;                  ///< the authors' drag form (0: none)
  std::optional<double> mu_n, mu_t;      ///< a friction split, when the job has one
  bool drain = false;                ///< simulated draining hopper (reinject = false): Q is c0 t0
  std::string provenance;            ///< an imported series: "measured" or "simulated" (else empty)
  std::int64_t experiment_id = 0;    ///< its experiment_series.id
  bool is_dp() const { return model == "dp_smooth" || model == "dp_rough"; }
  /// Q is a draining hopper's c0 t0 (docs/experiments.md), not a continuous flow rate: such
  /// series have their own figures and no crossover.
  bool rate_is_c0() const { return drain || !provenance.empty(); }
  std::vector<SeriesPoint> points;  ///< sorted by w
  std::vector<std::string> job_keys;
  std::optional<BeverlooFit> fit;
  std::string message;  ///< why there is no fit
  /// The same points fitted the way the paper's authors fitted theirs (fit_beverloo_bounded with
  /// BoundedFitOptions::authors(): bounded, unweighted, 2 < w < 19); beside the default, never
  /// instead of it.
  std::optional<BoundedBeverlooFit> authors_fit;
  std::string authors_message;
  /// The authors' fits with beta held at d - 3/2 and at d - 1/2 (fit_beverloo_fixed_beta, as
  /// their Fig. 2 and Appendix B): k and C of each.
  std::optional<BeverlooFit> authors_fixed_lo, authors_fixed_hi;
  /// Replicas fitted one by one (those with every width of the pooled fit), and the sample
  /// standard deviation of their betas (NaN below two): the run-to-run spread. The same for k
  /// of the free fit and of the authors' fits with beta held (the offset is what the paper's
  /// Fig. 7 maps; its spread over seeds is what a difference between two cells is judged by).
  int replica_fits = 0;
  double beta_replica_spread = NAN, k_replica_spread = NAN;
  /// Those replicas' own free fits (replica -> fit): what a crossover's run-to-run spread is
  /// fitted from (Crossover::spread).
  std::map<int, BeverlooFit> replica_fit;
  double k_at_beta_lo_replica_spread = NAN, k_at_beta_hi_replica_spread = NAN;
  /// The same for the held fits' C, as the spread of ln C (a relative spread): what a ratio of
  /// two Cs (Appendix B's limits, Appendix C's growth with N) is judged by beside the fits' errors.
  double log_C_at_beta_lo_replica_spread = NAN, log_C_at_beta_hi_replica_spread = NAN;
  /// Clogging as a result: per w, the time to a clog over the replicas (Kaplan-Meier, runs that
  /// ended flowing censored at their end); every w of a series in which some run clogged.
  struct ClogPoint {
    double w = 0, t_max = 0;
    KaplanMeier km;
  };
  std::vector<ClogPoint> clog_points;
  int clogged_points() const;
  ForceRatio force_ratio;
  /// The flowing points' w, Q and Q_err (what the Beverloo fit takes), in w order.
  void flowing_columns(std::vector<double>& w, std::vector<double>& Q, std::vector<double>& Q_err) const {
    for (const SeriesPoint& p : points)
      if (p.flowing()) {
        w.push_back(p.w);
        Q.push_back(p.Q);
        Q_err.push_back(p.Q_err);
      }
  }
};

/// A fit whose beta has a larger relative error than this is "not determined" (index.html).
inline constexpr double kBetaDeterminedRelErr = 0.25;
/// A free fit's k this many of its errors outside [0, smallest flowing w] follows no Beverloo
/// law; closer, the range holds it (the claims' "agree" is within 2 combined errors too).
inline constexpr double kBeverlooLawKSigmas = 2.0;
/// "ok", or "not determined: ..." naming why (beta's relative error; k outside [0, smallest w]).
std::string fit_quality(const Series& s);
/// True if the series' free fit puts k outside [0, smallest flowing w] by more than
/// kBeverlooLawKSigmas of k's errors: its Q(w) follows no Beverloo law (it curves more than
/// any with k >= 0 can, or k sits at the smallest width), so its beta is no Beverloo exponent,
/// however small its error. (A beta with a large error is still one, and a weighted fit can
/// take it.)
bool follows_no_beverloo_law(const Series& s);
/// That rule in words, as tables, figures and messages name it: "k outside [0, smallest w] by
/// more than 2 errors".
std::string no_beverloo_law_rule();

struct Crossover {
  std::string key, label;
  /// The same for every group that differs from this one only in the hopper angles (and in
  /// nothing else: not E_w, not the reinjection rule): the series of the paper's Fig. 6.
  std::string angle_family;
  int dimension = 2;
  std::vector<const Series*> finite;  ///< the finite lambda > 0 series with a fit, by lambda
  /// those of `finite` whose Q(w) follows no Beverloo law (follows_no_beverloo_law: k outside
  /// [0, smallest w]): drawn and listed, but not in the crossover fits, whose sigmoid is a law
  /// for Beverloo exponents (a beta with a large error stays in, weighted by it)
  std::vector<const Series*> no_beverloo_law;
  /// the series the crossover fits take: `finite` without `no_beverloo_law`
  int fitted_points() const { return static_cast<int>(finite.size() - no_beverloo_law.size()); }
  /// whether the crossover fits take this series of `finite`
  bool takes(const Series* s) const {
    return std::find(no_beverloo_law.begin(), no_beverloo_law.end(), s) == no_beverloo_law.end();
  }
  /// the finite lambda of its series without a fit (too few flowing widths): a lambda the group
  /// has, where the adaptive planner must not place a new series again
  std::vector<double> unfitted_lambda;
  /// those series themselves: a series needs no fit for what each run measures (the force ratio)
  std::vector<const Series*> unfitted;
  const Series* limit0 = nullptr;     ///< lambda = 0 (friction only)
  const Series* limit_inf = nullptr;  ///< lambda = inf (drag only)
  std::optional<CrossoverFit> fit;
  std::string message;
  /// Where `fit` is missing, a fit that is no measurement but says where the step is, which is
  /// where the adaptive planner places its next lambda: a singular fit taken out of `fit` (its b
  /// or lambda_c has no error; crossover groups' drop_if_degenerate), or the fit that takes the
  /// series of no_beverloo_law too when those without them are too few
  std::optional<CrossoverFit> design_fit;
  /// beta(lambda) with its plateaus free (fit_crossover_free_plateaus), beside the paper's fixed ones
  std::optional<CrossoverFit> fit_free;
  std::string message_free;
  /// The run-to-run spread of a crossover fit: the sigmoid fitted again to each replica's own
  /// exponents (the replicas with a free fit in every finite-lambda series of the group, the
  /// pooled fit's lambdas and no others), the sample standard deviation of log10 lambda_c and
  /// of b over those fits (NaN below two). The pooled fit's error says how well one set of
  /// exponents fixes lambda_c; this says how far another seed's set moves it.
  struct ReplicaSpread {
    int replicas = 0;  ///< replicas whose own crossover fit succeeded
    double log10_lambda_c = NAN, b = NAN;
    /// lambdas of the pooled fit that the replicas' own fits leave out: those with fewer than
    /// two replica fits (e.g. a costly lambda run once), so that the other lambdas still give a
    /// spread
    int lambdas_left_out = 0;
  };
  ReplicaSpread spread, spread_free;  ///< of fit (the paper's plateaus) and of fit_free
};

struct CampaignFits {
  std::vector<Series> series;
  std::vector<Crossover> crossovers;
};

/// Which flow rate a series is made of: Q (the default), or Appendix B's Q' = Q a_eff / a_avg
/// (the area that left counted with the packing's own particle area near the orifice, a_eff =
/// 1/rho_n), with its error.
enum class FlowRate { Q, QPrime };
/// Reads the campaigns of `scope` (by default the latest) and the experiment series (Q only),
/// and fits them. Never throws for unfittable data.
CampaignFits fit_campaign(db::Database& db, FlowRate rate = FlowRate::Q, const CampaignScope& scope = CampaignScope::latest());
/// One campaign's series (-1: the latest) with their Beverloo fits and its beta(lambda) groups,
/// no experiments: what the adaptive planner decides from.
CampaignFits fit_campaign_with_crossovers(db::Database& db, std::int64_t campaign, FlowRate rate = FlowRate::Q);
/// The imported experiment series (reports/experiment_series.cpp), appended and fitted.
void add_experiment_series(db::Database& db, CampaignFits& out);

/// Replaces the fit tables in one transaction.
void store_fits(db::Database& db, const CampaignFits& fits);
/// beverloo_fits.{csv,md} and crossover_fits.{csv,md} in dir.
void write_fit_tables(const CampaignFits& fits, const std::string& dir);
/// The Markdown table of the series fits (also used by the HTML report).
std::string format_lambda(double lambda);
/// "beta", "k,beta", ...: the parameters of a bounded fit that ended on a bound ("" for none).
std::string bound_names(const BoundedBeverlooFit& f);
/// A number in the fit tables: %.*g, "inf" / "-inf", "" for NaN (the exports keep precision).
std::string table_number(double v, int digits = 4);

}  // namespace beverloo
