#pragma once
/// \file hopper_model.h
/// \brief The model seam: what a particle model (SP disks/spheres, DP polygons) owns, so that
/// the hopper protocol (engine/protocol/hopper_run) is written once for all of them. A model
/// owns its force terms and their state, places and relaxes its particles, advances them by a
/// step, rebuilds a reinjected particle, and writes its own part of a checkpoint. The protocol
/// sees one body per particle (SP: the particle; DP: the polygon's centroid) and never branches
/// on the model. A new model: a class here with a static time_scales(const SimConfig&) (its
/// stiffest terms, for dt "auto"), a case for each in make_model.cpp, and its terms in the
/// generic tests (tests/physics/test_model_terms.cpp iterates over every term of every model
/// through terms()).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../config.h"
#include "../forces/force_field.h"
#include "../forces/force_term.h"
#include "../geometry/hopper.h"
#include "../integrate/exit_watch.h"
#include "../integrate/fire.h"
#include "../integrate/velocity_verlet.h"
#include "../io/h5.h"
#include "../neighbor/neighbor_list.h"
#include "../rng.h"
#include "../state.h"

namespace beverloo {

/// What the protocol does between the drift and the force evaluation of a step (count exits,
/// reinject): called by the model with the bodies up to date and a list over the bodies.
template <int D>
class StepHook {
 public:
  virtual ~StepHook() = default;
  /// exits_possible false: the model's drift saw no body where exit_watch() says the hook has
  /// work, and the hook may skip its sweep over the bodies.
  virtual void between_drift_and_force(ParticleState<D>& bodies, NeighborList<D>& body_list, bool exits_possible) = 0;
  /// Where the hook has work (ExitWatch), for bodies of these species.
  virtual ExitWatch exit_watch(const Species& sp) const = 0;
};

template <int D>
class HopperModel {
 public:
  virtual ~HopperModel() = default;

  /// Species constants of the bodies (sigma: what the protocol's geometry tests use).
  virtual Species body_species() const = 0;
  /// Random initial placement: resizes and fills the bodies (and the model's own state).
  virtual void place(ParticleState<D>& bodies, Rng& rng) = 0;
  /// FIRE with gravity and dissipation off, softened contacts (fire.max_pair_stiffness).
  virtual FireResult minimize(ParticleState<D>& bodies, double dt) = 0;
  /// Gravity and dissipation on, lists invalidated; at step 0 the forces of the start state.
  virtual void start_flow(ParticleState<D>& bodies) = 0;
  /// One velocity-Verlet step; bodies.step advances by one.
  virtual StepReport step(ParticleState<D>& bodies, double dt, StepHook<D>& hook) = 0;
  /// Throws InstabilityError, in the model's own words, if the step went unphysical.
  virtual void check_step(const StepReport& r, double t, double max_overlap) const = 0;
  /// Body i was just placed (position, velocity) by the reinjection: rebuild what hangs on it.
  virtual void reinjected(int i, ParticleState<D>& bodies, Rng& rng) = 0;
  /// Takes body i out of the simulation (a draining hopper): the last body takes its place,
  /// with everything that hangs on it (DP: its polygon's vertices); the lists are rebuilt.
  /// Called between drift and force, so that the step's forces miss the body.
  virtual void remove_body(int i, ParticleState<D>& bodies) = 0;
  /// Friction force on each body (for the |F^mu| observable).
  virtual void body_friction(const ParticleState<D>& bodies, VecArray<D>& out) = 0;
  /// Model-specific containment (DP: vertices, edges); throws InstabilityError.
  virtual void check_containment(double t) const = 0;
  /// A test of a reinjection spot beyond the body disks (DP: the polygons' edges); empty: none.
  virtual std::function<bool(int, const Vec<D>&)> spot_test() { return {}; }
  /// How far beyond a body's disk its particle may reach sideways (DP: a polygon's size).
  virtual double lateral_slack() const { return 0; }

  /// Degrees of freedom advanced per step (particles or vertices), for speed figures.
  virtual std::int64_t moving_points(const ParticleState<D>& bodies) const = 0;
  virtual std::int64_t neighbor_builds() = 0;
  /// The force terms, one by one, and the state they act on (for the generic tests).
  virtual std::vector<ForceTerm<D>*> terms() = 0;
  virtual ParticleState<D>& term_state(ParticleState<D>& bodies) = 0;
  /// The body that point i of term_state() belongs to (SP: i itself; DP: its polygon).
  virtual int body_of(int point) const = 0;
  /// Forces of the model's current state (lists and search bounds brought up to date); the
  /// bodies follow (DP: centroids). For tests and diagnostics that edit term_state().
  virtual ForceReport compute_forces(ParticleState<D>& bodies) = 0;
  /// Threads for step() (1: none); a model without threaded loops ignores it. The results
  /// must not depend on it.
  virtual void set_threads(int) {}
  /// Take over another run's model state (benchmarks); lists are rebuilt.
  virtual void copy_state_from(const HopperModel& other) = 0;

  /// The model's own part of a checkpoint (beside the bodies), and its reading. load runs
  /// after the bodies' species and exits are read and must leave the bodies consistent.
  virtual void save_checkpoint(hid_t file) const = 0;
  virtual void load_checkpoint(hid_t file, ParticleState<D>& bodies) = 0;
};

/// The model of c.model for dimension D (SP in 2D and 3D, the DP models in 2D).
template <int D>
std::unique_ptr<HopperModel<D>> make_model(const SimConfig& c, const Hopper<D>& hopper);

}  // namespace beverloo
