#include "sp_model.h"

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "../protocol/placement.h"

namespace beverloo {

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
