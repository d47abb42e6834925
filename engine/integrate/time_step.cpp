#include "time_step.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "../forces/harmonic_overlap.h"
#include "../dp/polygons.h"
#include "../state.h"
#include "../units.h"

namespace beverloo {

TimeStepChoice choose_time_step(const SimConfig& c) {
  const Species sp = Species::bidisperse(c.dimension, c.size_ratio);
  const char* names[2] = {"small", "large"};
  TimeStepChoice t;
  t.period_min = std::numeric_limits<double>::infinity();
  t.tau_min = std::numeric_limits<double>::infinity();
  // the damping time of the stronger friction coefficient (normal or tangential)
  const double mu_max = std::max(c.mu_normal(), c.mu_tangential());
  auto period = [](double m, double k) { return 2 * units::pi * std::sqrt(m / k); };
  auto consider_period = [&](double T, const std::string& term) {
    if (T < t.period_min) {
      t.period_min = T;
      t.period_term = term;
    }
  };
  auto consider_tau = [&](double tau, const std::string& term) {
    if (tau < t.tau_min) {
      t.tau_min = tau;
      t.tau_term = term;
    }
  };
  if (c.is_dp()) {
    // Per vertex (mass M/n_v); the contact acts on the reduced mass of two vertices.
    const DpShape shape = DpShape::from_config(c);
    const double nv = shape.n_v;
    for (int a = 0; a < 2; ++a) {
      const double mv = shape.vertex_mass[a], l0 = shape.l0[a];
      for (int b = a; b < 2; ++b) {
        const double m_red = mv * shape.vertex_mass[b] / (mv + shape.vertex_mass[b]);
        const double delta = 0.5 * (shape.delta[a] + shape.delta[b]);
        const std::string pair = std::string(names[a]) + "-" + names[b];
        consider_period(period(m_red, HarmonicOverlap::stiffness(c.dp.E_c, delta)), "dp.E_c (" + pair + " vertex contact)");
        if (mu_max > 0) consider_tau(m_red / mu_max, "mu (kinetic friction, " + pair + " vertices)");
      }
      const std::string who = std::string(names[a]) + " vertex";
      consider_period(period(mv, HarmonicOverlap::stiffness(c.E_w, 0.5 * shape.delta[a])), "E_w (wall, " + who + ")");
      // edge spring K_l n_v between two vertices; area: |grad a|^2 ~ l0^2 per vertex;
      // bending: moving one vertex by x turns three edge pairs, curvature 6 K_b/(n_v l0^4)
      consider_period(period(0.5 * mv, c.dp.K_l * nv), "dp.K_l (segment length, " + who + ")");
      consider_period(period(mv, c.dp.K_a * l0 * l0), "dp.K_a (area, " + who + ")");
      if (c.dp.K_b > 0) consider_period(period(mv, 6 * c.dp.K_b / (nv * l0 * l0 * l0 * l0)), "dp.K_b (bending, " + who + ")");
      if (c.zeta > 0 || c.drag_rate > 0)
        consider_tau(mv / (c.zeta / nv + c.drag_rate * mv), std::string(c.drag_rate > 0 ? "zeta, drag_rate" : "zeta") + " (drag, " + who + ")");
    }
  } else {
    for (int a = 0; a < 2; ++a) {
      for (int b = a; b < 2; ++b) {
        const double m_red = sp.mass[a] * sp.mass[b] / (sp.mass[a] + sp.mass[b]);
        const std::string pair = std::string(names[a]) + "-" + names[b];
        const double sig_ab = 0.5 * (sp.sigma[a] + sp.sigma[b]);
        consider_period(period(m_red, HarmonicOverlap::stiffness(c.pair_energy(sig_ab), sig_ab)),
                        "E_sp (" + pair + " contact)");
        if (mu_max > 0) consider_tau(m_red / mu_max, "mu (kinetic friction, " + pair + ")");
      }
      // wall: U = (E_w/2)(1 - d/(sigma/2))^2, contact distance sigma/2, infinite wall mass
      consider_period(period(sp.mass[a], HarmonicOverlap::stiffness(c.E_w, 0.5 * sp.sigma[a])),
                      std::string("E_w (wall, ") + names[a] + " particle)");
      if (c.zeta > 0 || c.drag_rate > 0)
        consider_tau(sp.mass[a] / (c.zeta + c.drag_rate * sp.mass[a]),
                    std::string(c.drag_rate > 0 ? "zeta, drag_rate" : "zeta") + " (drag, " + names[a] + " particle)");
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
