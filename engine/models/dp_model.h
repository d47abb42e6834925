#pragma once
/// \file dp_model.h
/// \brief Deformable polygons (physics.md 4), smooth or rough contacts, 2D: the vertices are
/// the state (engine/dp/dp_system); the protocol's bodies are the polygons' centroids, linked
/// by their own list for the pile finder and the reinjection.
#include <memory>

#include "../dp/dp_system.h"
#include "../integrate/time_step.h"
#include "hopper_model.h"

namespace beverloo {

class DpModel final : public HopperModel<2> {
 public:
  DpModel(const SimConfig& c, const Hopper<2>& hopper) : c_(c), dp_(c, hopper), bodies_list_(c.skin) {}

  /// The stiffest terms of c's polygons, per vertex (contacts, walls, shape springs, friction,
  /// drag), known before any model exists.
  static TimeScales time_scales(const SimConfig& c);

  Species body_species() const override { return dp_.body_species(); }
  void place(ParticleState<2>& bodies, Rng& rng) override;
  FireResult minimize(ParticleState<2>& bodies, double dt) override;
  void start_flow(ParticleState<2>& bodies) override;
  StepReport step(ParticleState<2>& bodies, double dt, StepHook<2>& hook) override;
  void check_step(const StepReport& r, double t, double max_overlap) const override;
  void reinjected(int i, ParticleState<2>& bodies, Rng& rng) override;
  void remove_body(int i, ParticleState<2>& bodies) override {
    dp_.remove_polygon(i);
    bodies.remove_swapping_last(i);
    bodies_list_.invalidate();
  }
  void body_friction(const ParticleState<2>&, VecArray<2>& out) override { dp_.body_friction(out); }
  /// The vertex force field's chunks and the integrator's loops on `threads` threads: the same
  /// bits for every count (DpForceField::set_threads).
  void set_threads(int threads) override { dp_.forces().set_threads(threads); }
  void check_containment(double t) const override { dp_.check_vertices(t); }
  std::function<bool(int, const Vec<2>&)> spot_test() override {
    return [this](int m, const Vec<2>& centre) { return dp_.spot_is_free(m, centre); };
  }
  double lateral_slack() const override { return dp_.shape().bounding_diameter(1); }
  std::int64_t moving_points(const ParticleState<2>&) const override { return dp_.verts().size(); }
  std::int64_t neighbor_builds() override { return dp_.forces().list().builds(); }
  std::vector<ForceTerm<2>*> terms() override { return dp_.forces().terms(); }
  ParticleState<2>& term_state(ParticleState<2>&) override { return dp_.verts(); }
  int body_of(int point) const override { return dp_.polygons().owner[point]; }
  ForceReport compute_forces(ParticleState<2>& bodies) override {
    const ForceReport r = dp_.forces().compute(dp_.verts());
    dp_.sync_bodies(bodies);
    return r;
  }
  void copy_state_from(const HopperModel<2>& other) override;
  void save_checkpoint(hid_t file) const override;
  void load_checkpoint(hid_t file, ParticleState<2>& bodies) override;

  DpSystem& system() { return dp_; }

 private:
  SimConfig c_;
  DpSystem dp_;
  NeighborList<2> bodies_list_;
};

}  // namespace beverloo
