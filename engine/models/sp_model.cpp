#include "sp_model.h"

#include <algorithm>
#include <limits>
#include <string>

#include "../forces/contact_laws.h"
#include "../forces/harmonic_overlap.h"
#include "../io/vec_io.h"
#include "../protocol/placement.h"
#include "core/errors.h"

namespace beverloo {

template <int D>
TimeScales SpModel<D>::time_scales(const SimConfig& c) {
  const Species sp = Species::bidisperse(c.dimension, c.size_ratio);
  const char* names[2] = {"small", "large"};
  const double mu_max = std::max(c.mu_normal(), c.mu_tangential());  // the stronger friction
  const NormalLawRow& law = normal_law(c.sp_contact_law);
  TimeScales s;
  for (int a = 0; a < 2; ++a) {
    for (int b = a; b < 2; ++b) {
      const double m_red = sp.mass[a] * sp.mass[b] / (sp.mass[a] + sp.mass[b]);
      const std::string pair = std::string(names[a]) + "-" + names[b];
      const double sig_ab = 0.5 * (sp.sigma[a] + sp.sigma[b]);
      s.oscillation(m_red, law.stiffness(law.energy_scale(c.E_sp, sig_ab), sig_ab), "E_sp (" + pair + " contact)");
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
  // a resumed run continues with the list of its checkpoint (the same rebuilds, the same order)
  if (!restored_list_) ff_.list().invalidate();
  restored_list_ = false;
  // Forces at the start (or the resumed) state: identical to those the uninterrupted run holds,
  // because the pair sums do not depend on when the list was built (see neighbor_list.h).
  if (bodies.step == 0) ff_.compute(bodies);
}

template <int D>
StepReport SpModel<D>::step(ParticleState<D>& bodies, double dt, StepHook<D>& hook) {
  // velocity_verlet_step in two sweeps over the particles (ForceField: drift_and_start_forces,
  // forces_and_kick), with the list kept here: the drift measures the displacements, and a due
  // rebuild sorts the particles by cell (the forces started with them) before the protocol
  // counts exits (it holds no index across steps, and the exit records name ids). The same
  // operations as drift(), evaluate() and kick() one after the other: the same bits
  // (tests/physics/test_fused_step.cpp). The report holds no energies (compute_forces() has them).
  NeighborList<D>& list = ff_.list();
  bool exits_possible = true;
  const bool moved = ff_.drift_and_start_forces(bodies, dt, hook.exit_watch(bodies.sp), exits_possible);
  if (list.due_after(moved)) list.build_sorting(bodies, hopper_, sort_scratch_);
  hook.between_drift_and_force(bodies, list, exits_possible);
  // a relocation without room, a drained particle: the exits are done with their indices
  if (list.forced()) list.build_sorting(bodies, hopper_, sort_scratch_);
  const typename ForceField<D>::StepForces out = ff_.forces_and_kick(bodies, dt);
  StepReport r;
  r.forces.max_overlap = out.max_overlap;
  r.finite = out.finite;
  ++bodies.step;
  return r;
}

template <int D>
void SpModel<D>::save_checkpoint(hid_t file) const {
  const auto snap = ff_.list().snapshot();
  H5Handle g = h5::create_group(file, "sp_list");
  h5::attr(g, "force", std::int64_t{snap.force});
  h5::attr(g, "builds", snap.builds);
  if (snap.force) return;
  h5::write(g, "x_ref", flatten<D>(snap.x_ref), {hsize_t(snap.x_ref.size()), hsize_t(D)});
  h5::write(g, "row_start", std::vector<std::int32_t>(snap.row_start.begin(), snap.row_start.end()));
  h5::write(g, "row_end", std::vector<std::int32_t>(snap.row_end.begin(), snap.row_end.end()));
  h5::write(g, "nbr", std::vector<std::int32_t>(snap.nbr.begin(), snap.nbr.end()));
  h5::write(g, "wall_mask", snap.wall_mask);
}

template <int D>
void SpModel<D>::load_checkpoint(hid_t file, ParticleState<D>& bodies) {
  H5Handle g = h5::open_group(file, "sp_list");
  typename NeighborList<D>::Snapshot snap;
  snap.force = h5::attr_int64(g, "force") != 0;
  snap.builds = h5::attr_int64(g, "builds");
  if (!snap.force) {
    snap.x_ref.resize(bodies.size());
    unflatten<D>(h5::read_doubles(g, "x_ref"), snap.x_ref, "sp_list/x_ref");
    auto ints = [&](const char* name) {
      const std::vector<std::int64_t> v = h5::read_int64(g, name);
      for (std::int64_t k : v)
        if (k < -1 || k > std::numeric_limits<int>::max())
          throw IoError(std::string("checkpoint: sp_list/") + name + " out of range");
      return std::vector<int>(v.begin(), v.end());
    };
    snap.row_start = ints("row_start");
    snap.row_end = ints("row_end");
    snap.nbr = ints("nbr");
    snap.wall_mask = h5::read_uint8(g, "wall_mask");
  }
  try {
    ff_.list().restore(std::move(snap), bodies.size());
  } catch (const std::invalid_argument& e) {
    throw IoError(std::string("checkpoint: ") + e.what());
  }
  restored_list_ = true;
}

template <int D>
void SpModel<D>::check_step(const StepReport& r, double t, double max_overlap) const {
  if (!r.finite) throw InstabilityError("NaN or infinite position/velocity at t = " + std::to_string(t));
  if (r.forces.max_overlap > max_overlap)
    throw InstabilityError("pair overlap 1 - r/sigma = " + std::to_string(r.forces.max_overlap) +
                           " beyond max_overlap = " + std::to_string(max_overlap) + " at t = " + std::to_string(t));
}

template class SpModel<2>;
template class SpModel<3>;

}  // namespace beverloo
