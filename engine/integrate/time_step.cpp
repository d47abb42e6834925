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
  {
    const double by_period = t.period_min / kAutoPeriodFraction, by_damping = t.tau_min / kAutoDampingFraction;
    if (kDefaultMaxDt <= by_period && kDefaultMaxDt <= by_damping)
      t.limiting_term = "the largest dt, 1e-3";
    else
      t.limiting_term = by_period <= by_damping ? t.period_term : t.tau_term;
  }
  if (!explicit_dt) {
    t.automatic = true;
    t.dt = std::min({kDefaultMaxDt, t.period_min / kAutoPeriodFraction, t.tau_min / kAutoDampingFraction});
    if (!(t.dt >= kSmallestDt)) {
      // a stiffness or a drag the engine cannot resolve in any run a machine finishes: refused
      // before anything is allocated, naming the parameter that sets it (the term's last one)
      const bool stiff = t.period_min / kAutoPeriodFraction <= t.tau_min / kAutoDampingFraction;
      const std::string term = stiff ? t.period_term : t.tau_term;
      std::string field = term.substr(0, term.find(" ("));
      if (field.rfind(", ") != std::string::npos) field = field.substr(field.rfind(", ") + 2);
      std::ostringstream msg;
      msg.precision(3);
      msg << "makes " << (stiff ? "the oscillation period " : "the damping time ") << (stiff ? t.period_min : t.tau_min)
          << " t0 (" << term << "), so dt \"auto\" would be " << t.dt << " t0; at least " << kSmallestDt
          << " t0 can be run (10^7 steps per t0)";
      throw ConfigError(field, msg.str());
    }
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
