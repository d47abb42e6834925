#include "time_step.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "../forces/harmonic_overlap.h"
#include "../state.h"
#include "../units.h"

namespace beverloo {

TimeStepChoice choose_time_step(const SimConfig& c) {
  const Species sp = Species::bidisperse(c.dimension, c.size_ratio);
  const char* names[2] = {"small", "large"};
  TimeStepChoice t;
  t.period_min = std::numeric_limits<double>::infinity();
  t.tau_min = std::numeric_limits<double>::infinity();
  auto period = [](double m, double k) { return 2 * units::pi * std::sqrt(m / k); };
  for (int a = 0; a < 2; ++a) {
    for (int b = a; b < 2; ++b) {
      const double m_red = sp.mass[a] * sp.mass[b] / (sp.mass[a] + sp.mass[b]);
      const double T = period(m_red, HarmonicOverlap::stiffness(c.E_sp, 0.5 * (sp.sigma[a] + sp.sigma[b])));
      if (T < t.period_min) {
        t.period_min = T;
        t.period_term = std::string("E_sp (") + names[a] + "-" + names[b] + " contact)";
      }
      if (c.mu > 0 && m_red / c.mu < t.tau_min) {
        t.tau_min = m_red / c.mu;
        t.tau_term = std::string("mu (kinetic friction, ") + names[a] + "-" + names[b] + ")";
      }
    }
    // wall: U = (E_w/2)(1 - d/(sigma/2))^2, contact distance sigma/2, infinite wall mass
    const double Tw = period(sp.mass[a], HarmonicOverlap::stiffness(c.E_w, 0.5 * sp.sigma[a]));
    if (Tw < t.period_min) {
      t.period_min = Tw;
      t.period_term = std::string("E_w (wall, ") + names[a] + " particle)";
    }
    if (c.zeta > 0 && sp.mass[a] / c.zeta < t.tau_min) {
      t.tau_min = sp.mass[a] / c.zeta;
      t.tau_term = std::string("zeta (drag, ") + names[a] + " particle)";
    }
  }
  t.largest_accepted = std::min(t.period_min / kRefusePeriodFraction, t.tau_min);
  if (!c.dt) {
    t.automatic = true;
    t.dt = std::min({kDefaultMaxDt, t.period_min / kAutoPeriodFraction, t.tau_min / kAutoDampingFraction});
    return t;
  }
  t.automatic = false;
  t.dt = *c.dt;
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
