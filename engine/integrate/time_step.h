#pragma once
/// \file time_step.h
/// \brief Time step from the stiffest term (physics.md 5). Each model names its time scales
/// (engine/models: SpModel::time_scales, DpModel::time_scales): for each harmonic term of
/// stiffness k acting on mass m (reduced mass for pairs) the period T = 2 pi sqrt(m/k); for each
/// damping term gamma acting on m the relaxation time tau = m/gamma. The rule here is the same
/// for every model:
///   dt = "auto": min(1e-3, T_min/15, tau_min/5)
///   explicit dt: refused if dt > T_min/6 or dt > tau_min, naming the term and the largest dt.
/// choose_time_step(const SimConfig&), which asks the configured model for its scales, is
/// declared in engine/models/model_time_step.h.
#include <limits>
#include <optional>
#include <string>

namespace beverloo {

/// The shortest oscillation period and damping time of a model, with the terms that set them.
class TimeScales {
 public:
  /// A harmonic term of stiffness k (energy / length^2) acting on mass m.
  void oscillation(double mass, double stiffness, const std::string& term);
  /// A damping term with relaxation time tau = m / gamma.
  void damping(double tau, const std::string& term);

  double period_min() const { return period_min_; }
  const std::string& period_term() const { return period_term_; }
  double tau_min() const { return tau_min_; }
  const std::string& tau_term() const { return tau_term_; }

 private:
  double period_min_ = std::numeric_limits<double>::infinity();
  std::string period_term_;
  double tau_min_ = std::numeric_limits<double>::infinity();
  std::string tau_term_;
};

struct TimeStepChoice {
  double dt = 0;
  double period_min = 0;       ///< shortest oscillation period T_min
  std::string period_term;     ///< the term that sets it, e.g. "E_sp (small-small contact)"
  double tau_min = 0;          ///< shortest damping time (infinite without dissipation)
  std::string tau_term;
  double largest_accepted = 0; ///< the largest explicit dt that would be accepted
  bool automatic = true;
  /// What sets dt "auto": the period term, the damping term or the 1e-3 cap (for an explicit dt,
  /// the term that would set dt "auto"). Friction or drag can set it: a friction-only DP job's dt
  /// is tau/5 of its vertex friction, half its contact's T/15.
  std::string limiting_term;
};

inline constexpr double kDefaultMaxDt = 1e-3;   ///< the paper's dt, the upper bound of "auto"
inline constexpr double kAutoPeriodFraction = 15;
inline constexpr double kRefusePeriodFraction = 6;
inline constexpr double kAutoDampingFraction = 5;
/// The smallest dt "auto" may choose (t0): below it a job takes more than 10^7 steps per t0 of
/// flow (days for one t0 of a large system), so its parameters are refused as beyond the engine.
inline constexpr double kSmallestDt = 1e-7;

/// The step for a model's time scales: automatic when explicit_dt is empty, else explicit_dt
/// checked; throws ConfigError("dt", ...) if an explicit dt is too large for the stiffest term.
TimeStepChoice choose_time_step(const std::optional<double>& explicit_dt, const TimeScales& scales);

}  // namespace beverloo
