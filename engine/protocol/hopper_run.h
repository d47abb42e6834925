#pragma once
/// \file hopper_run.h
/// \brief The hopper-flow protocol of physics.md 6 as a short driver over its components:
/// place at random, FIRE with gravity off, gravity on, flow with exits counted and particles
/// reinjected, measure until the error target, the time limit or a clog.
///
/// Every decision is taken at fixed step numbers (samples, checks, checkpoints), never by the
/// wall clock, so a run is a pure function of its parameters and seed, also across a resume.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "../config.h"
#include "../dp/dp_system.h"
#include "../forces/force_field.h"
#include "../models/hopper_model.h"
#include "thread_governor.h"
#include "../geometry/hopper.h"
#include "../models/model_time_step.h"
#include "../rng.h"
#include "exit_counter.h"
#include "flow_rate.h"
#include "observables.h"
#include "pile_finder.h"
#include "reinjector.h"
#include "run_result.h"
#include "run_hopper.h"

namespace beverloo {

template <int D>
class HopperRun : private StepHook<D> {
 public:
  /// run.stop_unreachable stops a run whose predicted error at t_max exceeds this times the target
  static constexpr double kUnreachableMargin = 1.5;
  HopperRun(const SimConfig& c, RunOptions options);
  ~HopperRun();

  /// Placement, FIRE and gravity on; or the checkpoint's state when resuming.
  void prepare();
  /// Flows until a stopping rule holds; writes result.h5 and summary.json if there is a directory.
  RunResult run();
  /// Advances the flow by exactly `steps` steps without the stopping rules (benchmarks, tests).
  void advance(std::int64_t steps);

  /// Per-particle state: SP particles, or the DP polygons' centroids (bodies).
  ParticleState<D>& state() { return s_; }
  /// The SP force field; throws std::logic_error for a DP run (which has none).
  ForceField<D>& forces();
  /// The vertex half of a DP run; nullptr for SP.
  DpSystem* dp();
  /// The model (SP or DP) behind the protocol.
  HopperModel<D>& model() { return *model_; }
  /// Continue from another run's state (benchmarks: every timed run from one warmed state).
  void copy_state_from(const HopperRun& other);
  /// Verlet-list builds so far (vertex list for DP).
  std::int64_t neighbor_builds();
  /// Degrees of freedom advanced per step: particles (SP) or vertices (DP).
  std::int64_t moving_points() const { return model_->moving_points(s_); }
  const Hopper<D>& hopper() const { return hopper_; }
  const FlowRecord& record() const { return rec_; }
  const TimeStepChoice& time_step() const { return ts_; }
  double time() const { return s_.step * ts_.dt; }

  void save_checkpoint(const std::string& path) const;
  /// another_job: the checkpoint may be of a job that differs only in its stopping rules
  void load_checkpoint(const std::string& path, bool another_job = false);

 private:
  void step_once();
  /// StepHook: exits counted, exited particles reinjected, between drift and forces.
  void between_drift_and_force(ParticleState<D>& bodies, NeighborList<D>& body_list, bool exits_possible) override;
  ExitWatch exit_watch(const Species& sp) const override { return exits_.watch(sp); }
  /// The reinjection of the exited particles listed by exits_ (list: over the particles, or
  /// over the DP bodies), between drift and force evaluation.
  void reinject_exited(NeighborList<D>& list);
  void place_and_minimize();
  /// The model of the job, and what the protocol takes from it (lateral slack, spot test).
  void make_fresh_model();
  /// Back to the state of a fresh run (an unusable checkpoint was partly read).
  void start_over();
  void check_containment() const;
  /// Bodies whose centre lies above the orifice plane and over the opening (lateral distance
  /// from the orifice axis below w/2): an arch that stops a flow holds at least one.
  int bodies_over_opening() const;
  /// Height above which a particle counts as escaped upward; returns the current top.
  double set_ceiling();
  RunResult finish(const std::string& status, const std::string& reason, const FlowRateEstimate& e);
  struct Stop {
    std::string status, reason;
  };
  /// The stopping rules of a check step (converged, unreachable) on its estimate.
  std::optional<Stop> check_rule(const FlowRateEstimate& est, std::int64_t step) const;
  /// After a checkpoint was loaded at step C: this job's rules at its check steps from
  /// `from_step` to C and its time limit. Throws NotOnTrajectory if they would have ended the run
  /// before C; returns the stop due at C itself (a final checkpoint, or a continued job whose
  /// rules are met there), if any.
  std::optional<Stop> replay_stopping_rules(std::int64_t from_step);
  std::int64_t min_steps() const;  ///< no rule but the clog's before this step (run.min_time)
  std::int64_t max_steps() const;  ///< the time limit's step: run.t_max, or run.min_time above it
  std::optional<Stop> stop_at_start_;  ///< a stop due at the loaded checkpoint's step
  void report_progress(const FlowRateEstimate& e, bool force);
  std::string path(const std::string& name) const;

  SimConfig c_;
  RunOptions opt_;
  TimeStepChoice ts_;
  Hopper<D> hopper_;
  ParticleState<D> s_;
  std::unique_ptr<HopperModel<D>> model_;  ///< SP or DP: forces, their state, placement
  double step_t_next_ = 0;                  ///< the time at the end of the step being taken
  Rng rng_;
  FlowRecord rec_;
  ExitCounter<D> exits_;
  Reinjector<D> reinjector_;
  FlowObservables<D> obs_;
  FlowRateEstimator estimator_;
  VecArray<D> friction_scratch_;
  /// drag coefficient of a whole particle (DP: polygon) per species, for the |F^zeta| observable
  std::array<double, 2> body_drag_{};
  PileFinder<D> pile_finder_;
  ThreadGovernor governor_{1};  ///< the thread count now (thread_governor.h)
  std::vector<std::uint8_t> in_pile_;
  std::int64_t fire_iterations_ = 0;
  double fire_max_force_ = 0;
  double ceiling_ = 0;            ///< a particle above this height has escaped upward
  double wall_seconds_before_ = 0;  ///< from earlier sessions (resume)
  int resumed_times_ = 0;
  std::chrono::steady_clock::time_point session_start_, last_progress_, last_checkpoint_;
  std::int64_t session_first_step_ = 0;
  /// particle-steps of this session (a draining hopper's N falls, so steps times N is not it)
  double session_particle_steps_ = 0;
  double particle_steps_this_session() const;
  struct Trajectory;
  std::unique_ptr<Trajectory> traj_;
};

}  // namespace beverloo
