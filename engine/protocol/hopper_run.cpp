#include "hopper_run.h"
#include "core/atomic_file.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "../geometry/make_hopper.h"
#include "../integrate/fire.h"
#include "../integrate/velocity_verlet.h"
#include "../io/result_file.h"
#include "../io/trajectory.h"
#include "../units.h"
#include "../models/dp_model.h"
#include "../models/sp_model.h"
#include "drain_fit.h"
#include "memory_estimate.h"
#include "placement.h"

namespace beverloo {
namespace {

/// The steps in `time` at dt, saturated: a time beyond any run (t_max 1e300: "no limit") is a
/// step count no run reaches, not llround's unspecified result (which ended such a run at its
/// first step). Half the int64 range, so that a step plus such a count cannot overflow.
std::int64_t steps_in(double time, double dt) {
  const double n = time / dt;
  constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max() / 2;
  return n >= static_cast<double>(kNever) ? kNever : std::llround(n);
}

std::int64_t steps_for(double time, double dt) { return std::max<std::int64_t>(1, steps_in(time, dt)); }

/// A checkpoint that is not on this job's trajectory (HopperRun::replay_stopping_rules).
struct NotOnTrajectory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string time_text(double t) {
  std::ostringstream o;
  o << t;
  return o.str();
}

/// c, once it is known to fit in memory: the first member's initialiser, so that a job this
/// machine cannot hold is refused before any member allocates.
const SimConfig& fits_in_memory(const SimConfig& c) {
  check_memory(c);
  return c;
}

}  // namespace

template <int D>
struct HopperRun<D>::Trajectory {
  H5mdTrajectory<D> writer;
};

template <int D>
HopperRun<D>::HopperRun(const SimConfig& c, RunOptions options)
    : c_(fits_in_memory(c)),
      opt_(std::move(options)),
      ts_(choose_time_step(c)),
      hopper_(make_hopper<D>(c)),
      rng_(c.effective_seed()),
      exits_(hopper_, c.reinjection.drop_depth_diameters, c.N),
      reinjector_(hopper_, c.reinjection, c.N),
      obs_(c),
      estimator_(c.run),
      pile_finder_(c.N),
      governor_(opt_.adapt_threads ? opt_.threads : 1) {
  make_fresh_model();
  body_drag_ = drag_coefficients(c_.zeta, c_.drag_rate, Species::bidisperse(D, c_.size_ratio).mass);
  rec_.exit_time.reserve(1 << 16);
  rec_.exit_particle.reserve(1 << 16);
  rec_.exit_size.reserve(1 << 16);
  if (opt_.progress == ProgressMode::Auto) opt_.progress = isatty(STDERR_FILENO) ? ProgressMode::Terminal : ProgressMode::Log;
}

template <int D>
HopperRun<D>::~HopperRun() = default;

template <int D>
void HopperRun<D>::make_fresh_model() {
  model_ = make_model<D>(c_, hopper_);
  model_->set_threads(governor_.active() ? governor_.threads() : opt_.threads);
  exits_.set_lateral_slack(model_->lateral_slack());
  if (auto test = model_->spot_test()) reinjector_.set_extra_test(std::move(test));
}

template <int D>
void HopperRun<D>::start_over() {
  // everything a checkpoint load writes, as the constructor left it
  s_ = ParticleState<D>{};
  make_fresh_model();
  rng_ = Rng(c_.effective_seed());
  rec_ = FlowRecord{};
  obs_ = FlowObservables<D>(c_);
  wall_seconds_before_ = 0;
  resumed_times_ = 0;
  fire_iterations_ = 0;
  fire_max_force_ = 0;
}

template <int D>
std::string HopperRun<D>::path(const std::string& name) const {
  return (std::filesystem::path(opt_.output_dir) / name).string();
}

template <int D>
ForceField<D>& HopperRun<D>::forces() {
  if (auto* sp = dynamic_cast<SpModel<D>*>(model_.get())) return sp->forces();
  throw std::logic_error("HopperRun::forces(): a DP run has no SP force field");
}

template <int D>
DpSystem* HopperRun<D>::dp() {
  if constexpr (D == 2) {
    if (auto* m = dynamic_cast<DpModel*>(model_.get())) return &m->system();
  }
  return nullptr;
}

template <int D>
void HopperRun<D>::place_and_minimize() {
  model_->place(s_, rng_);
  set_ceiling();
  const FireResult fr = model_->minimize(s_, ts_.dt);
  fire_iterations_ = fr.iterations;
  fire_max_force_ = fr.max_force;
  if (!fr.converged) {
    std::ostringstream m;
    m << "FIRE did not remove the initial overlaps: max force " << fr.max_force << " > fire.force_tol "
      << c_.fire.force_tol << " after " << fr.iterations << " iterations";
    throw InstabilityError(m.str());
  }
}

template <int D>
void HopperRun<D>::prepare() {
  const bool have_dir = !opt_.output_dir.empty();
  bool resumed = false;
  if (have_dir && opt_.resume && std::filesystem::exists(path("checkpoint.h5"))) {
    try {
      load_checkpoint(path("checkpoint.h5"));
      stop_at_start_ = replay_stopping_rules(s_.step);  // a final checkpoint: the stop that was due there
      resumed = true;
    } catch (const std::exception& e) {
      // damaged, another job's, or from an engine whose state differs: set it aside (kept for
      // whoever wants to look) and start the job over; the result is the same as a fresh run's
      const std::string aside = path("checkpoint.h5.unusable");
      std::error_code ec;
      std::filesystem::rename(path("checkpoint.h5"), aside, ec);
      if (ec) throw IoError("checkpoint.h5 cannot be read (" + std::string(e.what()) + ") nor moved aside: " + ec.message());
      std::fprintf(stderr, "checkpoint.h5 cannot be used (%s): moved to checkpoint.h5.unusable; starting over\n", e.what());
      start_over();
    }
  }
  bool continued = false;
  if (!resumed && have_dir && !opt_.continue_from.empty()) {
    try {
      if (!c_.reinject) throw NotOnTrajectory("a draining hopper is not continued");
      if (c_.run.trajectory_every_steps > 0) throw NotOnTrajectory("this job writes a trajectory from its start");
      load_checkpoint(opt_.continue_from, true);
      stop_at_start_ = replay_stopping_rules(0);
      // this job's engine time is its own (a campaign's sum of engine time counts each second
      // once); its one resume is the continuation
      wall_seconds_before_ = 0;
      resumed_times_ = 0;
      resumed = continued = true;
    } catch (const std::exception& e) {
      // another trajectory, or one this job's rules would have ended earlier: nothing lost but
      // the time the other job saved; this job runs from its beginning
      if (opt_.progress != ProgressMode::Quiet)
        std::fprintf(stderr, "not continuing %s (%s): running from the start\n", opt_.continue_from.c_str(), e.what());
      start_over();
      stop_at_start_.reset();
    }
  }
  if (resumed) {
    ++resumed_times_;
    if (opt_.progress != ProgressMode::Quiet)
      std::fprintf(stderr, "%s %s at step %lld (resume %d)\n", continued ? "continued the run of" : "resumed from",
                   continued ? opt_.continue_from.c_str() : "checkpoint.h5", static_cast<long long>(s_.step), resumed_times_);
  } else {
    place_and_minimize();
    check_containment();
    s_.step = 0;
  }
  model_->start_flow(s_);
  const double top = set_ceiling();
  if (have_dir && c_.run.trajectory_every_steps > 0)
    traj_.reset(new Trajectory{H5mdTrajectory<D>(path("trajectory.h5"), c_, s_, top, resumed_times_ ? s_.step : -1)});
  session_start_ = last_progress_ = last_checkpoint_ = std::chrono::steady_clock::now();
  session_first_step_ = s_.step;
}

template <int D>
void HopperRun<D>::copy_state_from(const HopperRun& other) {
  s_ = other.s_;
  model_->copy_state_from(*other.model_);
}

template <int D>
std::int64_t HopperRun<D>::neighbor_builds() {
  return model_->neighbor_builds();
}

template <int D>
double HopperRun<D>::set_ceiling() {
  double top = 0;
  for (int i = 0; i < s_.size(); ++i) top = std::max(top, s_.x[i][kUp<D>]);
  ceiling_ = 2 * top + 10 * c_.W;
  return top;
}

template <int D>
void HopperRun<D>::reinject_exited(NeighborList<D>& list) {
  list.update(s_, hopper_);  // a list valid for these positions: a canonical pile
  const bool lanes = c_.reinjection.rule == "lanes";  // the authors' rule needs no pile
  if (!lanes) pile_finder_.find(s_, list, hopper_, in_pile_);
  for (int i : exits_.to_reinject()) {
    ++rec_.reinjections;
    // the lane counter is the number of earlier reinjections: no extra checkpointed state
    const bool placed_as_ruled =
        lanes ? reinjector_.reinject_in_lane(s_, i, rec_.reinjections - 1, body_drag_[s_.species[i]] / s_.mass(i), &list)
              : reinjector_.reinject(s_, i, rng_, in_pile_, &list);
    if (!placed_as_ruled) ++rec_.reinjection_fallbacks;
    list.relocate(i, s_, hopper_);
    if (!lanes) in_pile_[i] = placed_as_ruled;  // resting on the pile; a fallback particle is in the air
    model_->reinjected(i, s_, rng_);
  }
}

template <int D>
void HopperRun<D>::between_drift_and_force(ParticleState<D>& bodies, NeighborList<D>& body_list,
                                           bool exits_possible) {
  if (exits_possible)
    exits_.update(bodies, step_t_next_, rec_);
  else
    exits_.none_to_count();
  if (exits_.to_reinject().empty()) return;
  if (c_.reinject) {
    reinject_exited(body_list);
  } else {
    // a draining hopper: a particle that has fallen the drop depth below the orifice leaves the
    // simulation; from the highest index down, so that the swapped-in last ones are still to come
    const std::vector<int>& gone = exits_.to_reinject();
    for (auto it = gone.rbegin(); it != gone.rend(); ++it) model_->remove_body(*it, bodies);
  }
}

template <int D>
void HopperRun<D>::step_once() {
  step_t_next_ = (s_.step + 1) * ts_.dt;
  if (!c_.reinject) session_particle_steps_ += s_.size();
  const StepReport r = model_->step(s_, ts_.dt, *this);
  // the same bits on every thread count: the count may follow the node's load between steps
  if (governor_.after_step()) model_->set_threads(governor_.threads());
  model_->check_step(r, time(), c_.max_overlap);
  rec_.max_overlap_seen = std::max(rec_.max_overlap_seen, r.forces.max_overlap);
}

template <int D>
void HopperRun<D>::check_containment() const {
  model_->check_containment(time());
  for (int i = 0; i < s_.size(); ++i) {
    if (!hopper_.contains(s_.x[i]) || s_.x[i][kUp<D>] > ceiling_ ||
        s_.x[i][kUp<D>] < -(c_.reinjection.drop_depth_diameters + 10) * s_.sigma(i)) {
      std::ostringstream m;
      m << "particle " << s_.id[i] << " left the container at t = " << time() << " (position " << s_.x[i].transpose() << ")";
      throw InstabilityError(m.str());
    }
  }
}

template <int D>
std::int64_t HopperRun<D>::min_steps() const {
  return steps_in(c_.run.min_time, ts_.dt);
}

template <int D>
std::int64_t HopperRun<D>::max_steps() const {
  return std::max<std::int64_t>(steps_in(c_.run.t_max, ts_.dt), min_steps());
}

template <int D>
std::optional<typename HopperRun<D>::Stop> HopperRun<D>::check_rule(const FlowRateEstimate& est, std::int64_t step) const {
  // a draining hopper has no steady state to converge to: it runs until it has drained
  if (!c_.reinject || step < min_steps() || !est.valid || est.t_end - est.t_start < c_.run.min_window) return std::nullopt;
  if (est.rel_err() <= c_.run.target_rel_err) return Stop{"converged", "relative error of Q reached run.target_rel_err"};
  // The error of a steady flow's mean falls as 1/sqrt of the window: the window the time limit
  // allows predicts the error there. Beyond the target by a margin (the present error is itself
  // uncertain), the rest of the run would be spent for a point the target cannot have.
  if (c_.run.stop_unreachable) {
    const double t_limit = std::max(c_.run.t_max, c_.run.min_time);
    const double predicted = est.rel_err() * std::sqrt((est.t_end - est.t_start) / (t_limit - est.t_start));
    if (predicted > kUnreachableMargin * c_.run.target_rel_err)
      return Stop{"unreachable", "at t_max SE(Q)/Q would be about " + std::to_string(predicted) + ", above " +
                                     std::to_string(kUnreachableMargin) + " x run.target_rel_err"};
  }
  return std::nullopt;
}

template <int D>
std::optional<typename HopperRun<D>::Stop> HopperRun<D>::replay_stopping_rules(std::int64_t from_step) {
  // Every rule is a function of the exit record up to its step (the estimate at step k bins only
  // exits before k dt), so the record of a later checkpoint answers for each earlier check. The
  // clog rule needs no replay: run.t_clog is part of the trajectory, equal in both jobs.
  const std::int64_t at = s_.step, limit = max_steps();
  if (limit < at)
    throw NotOnTrajectory("its time limit ends it at t = " + time_text(limit * ts_.dt) + ", before the checkpoint's t = " +
                          time_text(time()));
  const std::int64_t check_steps = steps_for(c_.run.check_interval, ts_.dt);
  const std::int64_t first = std::max<std::int64_t>(1, (from_step + check_steps - 1) / check_steps) * check_steps;
  for (std::int64_t k = first; k <= at; k += check_steps) {
    const std::optional<Stop> stop = check_rule(estimator_.estimate(rec_, k * ts_.dt), k);
    if (!stop) continue;
    if (k < at)
      throw NotOnTrajectory("its stopping rules end it at t = " + time_text(k * ts_.dt) + " (" + stop->status +
                            "), before the checkpoint's t = " + time_text(time()));
    return stop;
  }
  if (limit == at) return Stop{"time_limit", "reached run.t_max before the error target"};
  return std::nullopt;
}

template <int D>
void HopperRun<D>::advance(std::int64_t steps) {
  for (std::int64_t k = 0; k < steps; ++k) step_once();
}

template <int D>
RunResult HopperRun<D>::run() {
  const double dt = ts_.dt;
  const std::int64_t sample_steps = steps_for(c_.observables.sample_interval, dt);
  const std::int64_t check_steps = steps_for(c_.run.check_interval, dt);
  const std::int64_t ckpt_steps = c_.run.checkpoint_interval > 0 ? steps_for(c_.run.checkpoint_interval, dt) : 0;
  const std::int64_t traj_steps = c_.run.trajectory_every_steps;
  const std::int64_t max_steps = this->max_steps();
  constexpr std::int64_t kContainmentSteps = 100;
  const bool files = !opt_.output_dir.empty();
  FlowRateEstimate est;
  if (stop_at_start_) {  // the loaded checkpoint is where this job stops
    const Stop stop = *stop_at_start_;
    stop_at_start_.reset();
    return finish(stop.status, stop.reason, estimator_.estimate(rec_, time()));
  }
  if (traj_ && s_.step == 0) traj_->writer.write_frame(s_, 0.0);

  while (true) {
    step_once();
    const std::int64_t step = s_.step;
    const double t = time();
    if (step % sample_steps == 0) {
      model_->body_friction(s_, friction_scratch_);
      obs_.sample(s_, t, friction_scratch_, body_drag_);
    }
    if (traj_ && step % traj_steps == 0) traj_->writer.write_frame(s_, t);
    if (step % kContainmentSteps == 0) check_containment();
    if (t - rec_.last_exit_time >= c_.run.t_clog) {
      est = estimator_.estimate(rec_, t);
      // A draining hopper whose flow stopped with nothing over the opening has no arch: what
      // remains rests beside the orifice (a flat floor's corners, a dead zone) and will never
      // leave, as droplets in the experiments' flat-bottomed hoppers do not; that run has
      // drained what it can, and its N(t) is fitted as theirs is (docs/experiments.md).
      if (!c_.reinject && bodies_over_opening() == 0)
        return finish("drained", std::to_string(s_.size()) + " particles remain, none over the orifice (a dead zone " +
                                     "beside it, not a clog): no exit for t_clog = " + std::to_string(c_.run.t_clog),
                      est);
      return finish("clogged", "no particle exited for t_clog = " + std::to_string(c_.run.t_clog), est);
    }
    if (!c_.reinject && c_.N - static_cast<std::int64_t>(rec_.exit_time.size()) <= c_.drain.stop_below) {
      est = estimator_.estimate(rec_, t);
      return finish("drained", "at most drain.stop_below = " + std::to_string(c_.drain.stop_below) +
                                   " particles remain in the hopper", est);
    }
    if (step % check_steps == 0) {
      if (opt_.progress_step) opt_.progress_step->store(step, std::memory_order_relaxed);
      est = estimator_.estimate(rec_, t);
      report_progress(est, false);
      if (const auto stop = check_rule(est, step)) return finish(stop->status, stop->reason, est);
    }
    if (step >= max_steps) {
      est = estimator_.estimate(rec_, t);
      return finish("time_limit", "reached run.t_max before the error target", est);
    }
    if (files && ckpt_steps && step % ckpt_steps == 0) {
      save_checkpoint(path("checkpoint.h5"));
      last_checkpoint_ = std::chrono::steady_clock::now();
    } else if (files && opt_.checkpoint_wall_seconds > 0 && step % kContainmentSteps == 0) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_checkpoint_).count() >= opt_.checkpoint_wall_seconds) {
        save_checkpoint(path("checkpoint.h5"));
        last_checkpoint_ = now;
      }
    }
    if (opt_.stop_request && opt_.stop_request->load(std::memory_order_relaxed)) {
      if (files) save_checkpoint(path("checkpoint.h5"));
      RunResult r;
      r.status = "interrupted";
      r.stop_reason = "stopped by a signal at t = " + std::to_string(t) + "; checkpoint written";
      r.steps = step;
      r.t_end = t;
      if (opt_.progress == ProgressMode::Terminal) std::fputc('\n', stderr);
      return r;
    }
    if (opt_.progress == ProgressMode::Terminal && (step & 1023) == 0) report_progress(est, false);
  }
}

template <int D>
int HopperRun<D>::bodies_over_opening() const {
  int n = 0;
  for (int i = 0; i < s_.size(); ++i)
    n += s_.x[i][D - 1] > 0 && Hopper<D>::lateral(s_.x[i]) < hopper_.orifice_half_width();
  return n;
}

template <int D>
double HopperRun<D>::particle_steps_this_session() const {
  return c_.reinject ? (s_.step - session_first_step_) * double(s_.size()) : session_particle_steps_;
}

template <int D>
void HopperRun<D>::report_progress(const FlowRateEstimate& e, bool force) {
  if (opt_.progress == ProgressMode::Quiet) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_progress_).count();
  const bool terminal = opt_.progress == ProgressMode::Terminal;
  if (!force && since < (terminal ? 0.25 : 10.0)) return;
  last_progress_ = now;
  const double wall = std::chrono::duration<double>(now - session_start_).count();
  const double rate = wall > 0 ? particle_steps_this_session() / wall : 0;
  char line[256];
  // Q and the window only once the window is open and long enough for an error (before that
  // the estimator's numbers are placeholders, and a window "80-40" would be nonsense)
  if (e.valid && e.t_end > e.t_start)
    std::snprintf(line, sizeof line, "t = %.1f / %.0f  exits %lld  Q = %.4g +- %.2g (%.1f%%)  window %.0f-%.0f  %.3g particle-steps/s",
                  time(), c_.run.t_max, static_cast<long long>(rec_.exit_time.size()), e.Q, e.Q_err,
                  e.Q > 0 ? 100 * e.Q_err / e.Q : 0.0, e.t_start, e.t_end, rate);
  else
    std::snprintf(line, sizeof line, "t = %.1f / %.0f  exits %lld  transient (no measurement window yet)  %.3g particle-steps/s",
                  time(), c_.run.t_max, static_cast<long long>(rec_.exit_time.size()), rate);
  if (terminal)
    std::fprintf(stderr, "\r\033[K%s", line);
  else
    std::fprintf(stderr, "[beverloo] %s\n", line);
  std::fflush(stderr);
}

template <int D>
RunResult HopperRun<D>::finish(const std::string& status, const std::string& reason, const FlowRateEstimate& e) {
  RunResult r;
  r.status = status;
  r.stop_reason = reason;
  r.clogged = status == "clogged";
  if (r.clogged) {
    r.clog_time = rec_.last_exit_time;
    r.clog_detected_time = time();
  }
  // A clogged run has Q = 0 (physics.md 7); its pre-clog rate stays visible in the rate series.
  r.Q = r.clogged ? 0 : e.Q;
  r.Q_err = r.clogged ? 0 : e.Q_err;
  r.window_start = e.t_start;
  r.window_end = e.t_end;
  r.exits_in_window = e.exits_in_window;
  r.exits_total = static_cast<std::int64_t>(rec_.exit_time.size());
  if (!c_.reinject) {
    // a draining hopper: Q is c0 (per t0) of dN/dt = -c0 sqrt(N) over the steady exits; a fit
    // without enough exits leaves Q = 0 (not a flowing point) and says why
    r.draining = true;
    r.n_initial = c_.N;
    r.n_remaining = c_.N - static_cast<int>(r.exits_total);
    r.drain = fit_drain(rec_.exit_time, c_.N, c_.drain.fit_skip, c_.drain.block_exits);
    r.Q = !r.clogged && r.drain.ok ? r.drain.c0 : 0;
    r.Q_err = !r.clogged && r.drain.ok ? r.drain.c0_err : 0;
    if (r.drain.ok) {
      r.window_start = r.drain.t_first;
      r.window_end = r.drain.t_last;
      r.exits_in_window = r.drain.exits_used;
    } else {
      r.stop_reason += "; no fit: " + r.drain.message;
    }
  }
  r.Q_rel_err = (r.Q > 0) ? r.Q_err / r.Q : 0;
  const ObservableSummary o = obs_.summarize(e.t_start);
  r.rho_n = o.rho_n;
  r.rho_n_err = o.rho_n_err;
  r.a_eff = o.rho_n > 0 ? 1.0 / o.rho_n : 0;
  const double a_avg = s_.sp.mean_ref_size();
  r.Q_prime = r.Q * r.a_eff / a_avg;
  r.Q_prime_err = r.Q_err * r.a_eff / a_avg;
  r.mean_F_drag = o.mean_F_drag;
  r.mean_F_friction = o.mean_F_friction;
  r.force_ratio = o.force_ratio;
  r.force_ratio_err = o.force_ratio_err;
  r.profile_h = o.h;
  r.profile_v_g = o.v_g;
  r.profile_v_g_err = o.v_g_err;
  r.rate_bin = c_.run.rate_bin;
  r.rate = estimator_.rates();
  r.exit_time = rec_.exit_time;
  r.exit_size = rec_.exit_size;
  r.exit_particle = rec_.exit_particle;
  r.dt = ts_.dt;
  r.dt_limiting_term = ts_.limiting_term;
  r.seed = c_.effective_seed();
  r.steps = s_.step;
  r.t_end = time();
  r.fire_iterations = fire_iterations_;
  r.fire_max_force = fire_max_force_;
  r.reinjections = rec_.reinjections;
  r.reinjection_fallbacks = rec_.reinjection_fallbacks;
  r.max_overlap_seen = rec_.max_overlap_seen;
  const double session = std::chrono::duration<double>(std::chrono::steady_clock::now() - session_start_).count();
  r.wall_seconds = wall_seconds_before_ + session;
  r.particle_steps_per_second = session > 0 ? particle_steps_this_session() / session : 0;
  r.neighbor_builds = neighbor_builds();
  r.resumed_times = resumed_times_;
  report_progress(e, true);
  if (opt_.progress == ProgressMode::Terminal) std::fputc('\n', stderr);
  if (!opt_.output_dir.empty()) {
    // the state where the run stopped, before the result: a job that only stops later continues
    // it (RunOptions::continue_from), and a crash before the result resumes to this same stop;
    // not where no checkpoint was asked for at all (no cadence, no wall-clock checkpoints)
    const bool checkpoints = c_.run.checkpoint_interval > 0 || opt_.checkpoint_wall_seconds > 0;
    if (c_.reinject && !r.clogged && checkpoints) save_checkpoint(path("checkpoint.h5"));
    write_result_file(path("result.h5"), c_, r);
    write_text_atomically(path("summary.json"), r.summary_json().dump(2) + "\n");
  }
  return r;
}

RunResult run_hopper(const SimConfig& c, const RunOptions& options) {
  if (c.dimension == 2) {
    HopperRun<2> run(c, options);
    run.prepare();
    return run.run();
  }
  HopperRun<3> run(c, options);
  run.prepare();
  return run.run();
}

template class HopperRun<2>;
template class HopperRun<3>;

}  // namespace beverloo
