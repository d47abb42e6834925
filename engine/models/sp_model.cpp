#include "sp_model.h"

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "../forces/harmonic_overlap.h"
#include "../protocol/placement.h"

namespace beverloo {

template <int D>
TimeScales SpModel<D>::time_scales(const SimConfig& c) {
  const Species sp = Species::bidisperse(c.dimension, c.size_ratio);
  const char* names[2] = {"small", "large"};
  const double mu_max = std::max(c.mu_normal(), c.mu_tangential());  // the stronger friction
  TimeScales s;
  for (int a = 0; a < 2; ++a) {
    for (int b = a; b < 2; ++b) {
      const double m_red = sp.mass[a] * sp.mass[b] / (sp.mass[a] + sp.mass[b]);
      const std::string pair = std::string(names[a]) + "-" + names[b];
      const double sig_ab = 0.5 * (sp.sigma[a] + sp.sigma[b]);
      s.oscillation(m_red, HarmonicOverlap::stiffness(c.pair_energy(sig_ab), sig_ab), "E_sp (" + pair + " contact)");
      if (mu_max > 0) s.damping(m_red / mu_max, "mu (kinetic friction, " + pair + ")");
    }
    // wall: U = (E_w/2)(1 - d/(sigma/2))^2, contact distance sigma/2, infinite wall mass
    s.oscillation(sp.mass[a], HarmonicOverlap::stiffness(c.E_w, 0.5 * sp.sigma[a]),
                  std::string("E_w (wall, ") + names[a] + " particle)");
    if (c.zeta > 0 || c.drag_rate > 0)
      s.damping(sp.mass[a] / (c.zeta + c.drag_rate * sp.mass[a]),
                std::string(c.drag_rate > 0 ? "zeta, drag_rate" : "zeta") + " (drag, " + names[a] + " particle)");
  }
  return s;
}

template <int D>
void SpModel<D>::place(ParticleState<D>& bodies, Rng& rng) {
  place_randomly(bodies, c_, hopper_, rng);
}

template <int D>
FireResult SpModel<D>::minimize(ParticleState<D>& bodies, double dt) {
  // a softened copy of the force field: FIRE removes overlaps, it does not resolve stiff ones
  SimConfig soft = c_;
  soft.E_sp = std::min(c_.E_sp, c_.fire.max_pair_stiffness);
  ForceField<D> minimiser_forces(soft, hopper_);
  minimiser_forces.set_gravity(0);
  minimiser_forces.set_dissipation(false);
  return fire_minimize(bodies, minimiser_forces, c_.fire, dt);
}

template <int D>
void SpModel<D>::start_flow(ParticleState<D>& bodies) {
  ff_.set_gravity(c_.gravity);
  ff_.set_dissipation(true);
  ff_.list().invalidate();
  // Forces at the start (or the resumed) state: identical to those the uninterrupted run holds,
  // because the pair sums do not depend on when the list was built (see neighbor_list.h).
  if (bodies.step == 0) ff_.compute(bodies);
}

template <int D>
StepReport SpModel<D>::step(ParticleState<D>& bodies, double dt, StepHook<D>& hook) {
  return velocity_verlet_step(bodies, ff_, dt,
                              [&](ParticleState<D>& st) { hook.between_drift_and_force(st, ff_.list()); });
}

template <int D>
void SpModel<D>::check_step(const StepReport& r, double t, double max_overlap) const {
  if (!r.finite) throw InstabilityError("NaN or infinite position/velocity at t = " + std::to_string(t));
  if (r.forces.max_overlap > max_overlap)
    throw InstabilityError("pair overlap 1 - r/sigma = " + std::to_string(r.forces.max_overlap) + " beyond max_overlap = " +
                           std::to_string(max_overlap) + " at t = " + std::to_string(t));
}

template class SpModel<2>;
template class SpModel<3>;

}  // namespace beverloo
