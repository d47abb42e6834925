#include "time_step.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "../units.h"

namespace beverloo {

void TimeScales::oscillation(double mass, double stiffness, const std::string& term) {
  const double T = 2 * units::pi * std::sqrt(mass / stiffness);
  if (T < period_min_) {  // strict: on a tie the first term named keeps the blame
    period_min_ = T;
    period_term_ = term;
  }
}

void TimeScales::damping(double tau, const std::string& term) {
  if (tau < tau_min_) {
    tau_min_ = tau;
    tau_term_ = term;
  }
}

TimeStepChoice choose_time_step(const std::optional<double>& explicit_dt, const TimeScales& s) {
  TimeStepChoice t;
  t.period_min = s.period_min();
  t.period_term = s.period_term();
  t.tau_min = s.tau_min();
  t.tau_term = s.tau_term();
  t.largest_accepted = std::min(t.period_min / kRefusePeriodFraction, t.tau_min);
  if (!explicit_dt) {
    t.automatic = true;
    t.dt = std::min({kDefaultMaxDt, t.period_min / kAutoPeriodFraction, t.tau_min / kAutoDampingFraction});
    return t;
  }
  t.automatic = false;
  t.dt = *explicit_dt;
  if (t.dt > t.largest_accepted) {
    const bool stiff = t.period_min / kRefusePeriodFraction <= t.tau_min;
    std::ostringstream msg;
    msg.precision(3);
    msg << t.dt << " is unstable for " << (stiff ? t.period_term : t.tau_term) << ": ";
    if (stiff)
      msg << "oscillation period " << t.period_min << " needs dt <= T/" << kRefusePeriodFraction;
    else
      msg << "damping time " << t.tau_min << " needs dt <= tau";
    msg << "; the largest accepted dt is " << t.largest_accepted << " (or use \"auto\")";
    throw ConfigError("dt", msg.str());
  }
  return t;
}

}  // namespace beverloo
