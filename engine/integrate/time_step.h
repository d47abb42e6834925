#pragma once
/// \file time_step.h
/// \brief Time step from the stiffest term (physics.md 5). For each harmonic term of stiffness k
/// acting on mass m (reduced mass for pairs) the period is T = 2 pi sqrt(m/k); for each damping
/// term gamma acting on m the relaxation time is tau = m/gamma.
///   dt = "auto": min(1e-3, T_min/15, tau_min/5)
///   explicit dt: refused if dt > T_min/6 or dt > tau_min, naming the term and the largest dt.
#include <string>

#include "../config.h"

namespace beverloo {

struct TimeStepChoice {
  double dt = 0;
  double period_min = 0;       ///< shortest oscillation period T_min
  std::string period_term;     ///< the term that sets it, e.g. "E_sp (small-small contact)"
  double tau_min = 0;          ///< shortest damping time (infinite without dissipation)
  std::string tau_term;
  double largest_accepted = 0; ///< the largest explicit dt that would be accepted
  bool automatic = true;
};

inline constexpr double kDefaultMaxDt = 1e-3;   ///< the paper's dt, the upper bound of "auto"
inline constexpr double kAutoPeriodFraction = 15;
inline constexpr double kRefusePeriodFraction = 6;
inline constexpr double kAutoDampingFraction = 5;

/// Throws ConfigError("dt", ...) if an explicit dt is too large for the stiffest term.
TimeStepChoice choose_time_step(const SimConfig& c);

}  // namespace beverloo
