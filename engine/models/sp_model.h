#pragma once
/// \file sp_model.h
/// \brief Soft particles (physics.md 3): one body per particle, the SP force field over them.
#include "../forces/force_field.h"
#include "../geometry/hopper.h"
#include "../integrate/time_step.h"
#include "hopper_model.h"

namespace beverloo {

template <int D>
class SpModel final : public HopperModel<D> {
 public:
  SpModel(const SimConfig& c, const Hopper<D>& hopper) : c_(c), hopper_(hopper), ff_(c, hopper) {}

  /// The stiffest terms of c's soft particles (pair contacts, walls, friction, drag), known
  /// before any model exists so that a sweep can refuse an unstable dt.
  static TimeScales time_scales(const SimConfig& c);

  Species body_species() const override { return Species::bidisperse(D, c_.size_ratio); }
  void place(ParticleState<D>& bodies, Rng& rng) override;
  FireResult minimize(ParticleState<D>& bodies, double dt) override;
  void start_flow(ParticleState<D>& bodies) override;
  StepReport step(ParticleState<D>& bodies, double dt, StepHook<D>& hook) override;
  void check_step(const StepReport& r, double t, double max_overlap) const override;
  /// Its force start (gravity, drag) for its new velocity: step() started the forces in the drift.
  void reinjected(int i, ParticleState<D>& bodies, Rng&) override { ff_.start_force_of(bodies, i); }
  void remove_body(int i, ParticleState<D>& bodies) override {
    bodies.remove_swapping_last(i);
    ff_.list().invalidate();
  }
  void body_friction(const ParticleState<D>& bodies, VecArray<D>& out) override { ff_.contact().friction_forces(bodies, out); }
  void check_containment(double) const override {}
  std::int64_t moving_points(const ParticleState<D>& bodies) const override { return bodies.size(); }
  std::int64_t neighbor_builds() override { return ff_.list().builds(); }
  std::vector<ForceTerm<D>*> terms() override { return ff_.terms(); }
  ParticleState<D>& term_state(ParticleState<D>& bodies) override { return bodies; }
  int body_of(int point) const override { return point; }
  ForceReport compute_forces(ParticleState<D>& bodies) override { return ff_.compute(bodies); }
  void copy_state_from(const HopperModel<D>&) override { ff_.list().invalidate(); }
  /// The bodies are the state, and the list: its order and rebuild schedule shape the sums.
  void save_checkpoint(hid_t file) const override;
  void load_checkpoint(hid_t file, ParticleState<D>& bodies) override;

  void set_threads(int threads) override { ff_.set_threads(threads); }
  ForceField<D>& forces() { return ff_; }

 private:
  SimConfig c_;
  const Hopper<D>& hopper_;
  ForceField<D> ff_;
  ParticleState<D> sort_scratch_;  ///< the copies of a sort by cell (no allocation once warm)
  bool restored_list_ = false;     ///< the list came from a checkpoint: start_flow keeps it
};

}  // namespace beverloo
