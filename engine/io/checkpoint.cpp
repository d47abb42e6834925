/// \file checkpoint.cpp
/// \brief HopperRun's checkpoints: the complete state (positions, velocities, forces, exit flags,
/// RNG state, step, every accumulator), written to checkpoint.h5.tmp, fsync'ed and renamed.
#include <chrono>

#include "core/atomic_file.h"
#include "../protocol/hopper_run.h"
#include "h5.h"
#include "vec_io.h"
#include "core/version.h"

namespace beverloo {

template <int D>
void HopperRun<D>::save_checkpoint(const std::string& target) const {
  PendingFile file(target);  // removed if anything below fails (a full disk)
  {
    H5Handle f = h5::create_file(file.path());
    h5::attr(f, "format", std::string("beverloo-checkpoint"));
    h5::attr(f, "format_version", std::int64_t{2});  // 2: particle ids, the model's lists
    h5::attr(f, "engine_version", std::string(BEVERLOO_VERSION));
    h5::attr(f, "job_json", c_.to_json().dump());
    h5::attr(f, "step", s_.step);
    const double session = std::chrono::duration<double>(std::chrono::steady_clock::now() - session_start_).count();
    h5::attr(f, "wall_seconds", wall_seconds_before_ + session);
    h5::attr(f, "resumed_times", std::int64_t{resumed_times_});
    h5::attr(f, "fire_iterations", fire_iterations_);
    h5::attr(f, "fire_max_force", fire_max_force_);
    H5Handle p = h5::create_group(f, "particles");
    h5::write(p, "x", flatten<D>(s_.x), {hsize_t(s_.size()), hsize_t(D)});
    h5::write(p, "v", flatten<D>(s_.v), {hsize_t(s_.size()), hsize_t(D)});
    h5::write(p, "f", flatten<D>(s_.f), {hsize_t(s_.size()), hsize_t(D)});
    h5::write(p, "species", s_.species);
    h5::write(p, "exited", s_.exited);
    h5::write(p, "id", std::vector<std::int64_t>(s_.id.begin(), s_.id.end()));
    model_->save_checkpoint(f);  // the model's own state (DP: the vertices)
    const auto& st = rng_.state();
    h5::write(f, "rng_state", std::vector<std::uint64_t>(st.begin(), st.end()));
    H5Handle r = h5::create_group(f, "record");
    h5::write(r, "exit_time", rec_.exit_time);
    h5::write(r, "exit_particle", rec_.exit_particle);
    h5::write(r, "exit_size", rec_.exit_size);
    h5::attr(r, "last_exit_time", rec_.last_exit_time);
    h5::attr(r, "reinjections", rec_.reinjections);
    h5::attr(r, "reinjection_fallbacks", rec_.reinjection_fallbacks);
    h5::attr(r, "max_overlap_seen", rec_.max_overlap_seen);
    H5Handle o = h5::create_group(f, "observables");
    h5::write(o, "block_scalars", obs_.block_scalars);
    h5::write(o, "block_profile", obs_.block_profile);
    h5::flush(f, file.path());  // a flush that failed leaves an incomplete file: not committed
  }
  file.commit();
}

template <int D>
void HopperRun<D>::load_checkpoint(const std::string& source, bool another_job) {
  H5Handle f = h5::open_file(source);
  if (h5::attr_string(f, "format") != "beverloo-checkpoint") throw IoError(source + " is not a beverloo checkpoint");
  // another engine sums the forces in another order: continuing its state would give a result
  // that neither engine gives straight through (prepare() sets the file aside and starts over)
  const std::string engine = h5::attr_string(f, "engine_version");
  if (engine != BEVERLOO_VERSION)
    throw IoError(source + " was written by engine " + engine + ", this is " + BEVERLOO_VERSION);
  const std::string job = h5::attr_string(f, "job_json");
  if (job != c_.to_json().dump()) {
    // another job on the same trajectory (only its stopping rules differ): HopperRun::prepare
    // then checks that this job's rules would not have stopped it before the checkpoint's step
    bool same_trajectory = false;
    if (another_job) {
      try {
        same_trajectory = SimConfig::from_json(nlohmann::json::parse(job)).trajectory_json() == c_.trajectory_json();
      } catch (const std::exception&) {
      }
    }
    if (!same_trajectory)
      throw ConfigError("job", another_job ? "follows another trajectory than the job of the checkpoint " + source +
                                                 " (they differ in more than run.t_max, run.target_rel_err, "
                                                 "run.stop_unreachable and run.min_time)"
                                           : "differs from the job of the checkpoint " + source +
                                                 "; refusing to resume a different job");
  }
  s_.sp = model_->body_species();
  H5Handle p = h5::open_group(f, "particles");
  // a draining hopper's checkpoint holds the particles still in it (1 .. N)
  const int n = static_cast<int>(h5::read_uint8(p, "species").size());
  if (n < 1 || n > c_.N || (c_.reinject && n != c_.N))
    throw IoError("checkpoint: " + std::to_string(n) + " particles where the job has N = " + std::to_string(c_.N));
  s_.resize(n);
  unflatten<D>(h5::read_doubles(p, "x"), s_.x, "x");
  unflatten<D>(h5::read_doubles(p, "v"), s_.v, "v");
  unflatten<D>(h5::read_doubles(p, "f"), s_.f, "f");
  s_.species = h5::read_uint8(p, "species");
  s_.exited = h5::read_uint8(p, "exited");
  const std::vector<std::int64_t> ids = h5::read_int64(p, "id");
  if (static_cast<int>(s_.species.size()) != n || static_cast<int>(s_.exited.size()) != n ||
      static_cast<int>(ids.size()) != n)
    throw IoError("checkpoint: particle arrays have the wrong size");
  std::vector<std::uint8_t> seen(c_.N, 0);
  for (int i = 0; i < n; ++i) {
    if (ids[i] < 0 || ids[i] >= c_.N || seen[ids[i]]++) throw IoError("checkpoint: particle ids are not distinct ids below N");
    s_.id[i] = static_cast<std::int32_t>(ids[i]);
  }
  for (int i = 0; i < n; ++i) s_.inv_mass[i] = 1.0 / s_.sp.mass[s_.species[i]];
  model_->load_checkpoint(f, s_);
  s_.step = h5::attr_int64(f, "step");
  const auto st = h5::read_uint64(f, "rng_state");
  if (st.size() != 4) throw IoError("checkpoint: bad rng_state");
  rng_.set_state({st[0], st[1], st[2], st[3]});
  H5Handle r = h5::open_group(f, "record");
  rec_.exit_time = h5::read_doubles(r, "exit_time");
  rec_.exit_particle = h5::read_int64(r, "exit_particle");
  rec_.exit_size = h5::read_doubles(r, "exit_size");
  rec_.last_exit_time = h5::attr_double(r, "last_exit_time");
  rec_.reinjections = h5::attr_int64(r, "reinjections");
  rec_.reinjection_fallbacks = h5::attr_int64(r, "reinjection_fallbacks");
  rec_.max_overlap_seen = h5::attr_double(r, "max_overlap_seen");
  H5Handle o = h5::open_group(f, "observables");
  obs_.block_scalars = h5::read_doubles(o, "block_scalars");
  obs_.block_profile = h5::read_doubles(o, "block_profile");
  wall_seconds_before_ = h5::attr_double(f, "wall_seconds");
  resumed_times_ = static_cast<int>(h5::attr_int64(f, "resumed_times"));
  fire_iterations_ = h5::attr_int64(f, "fire_iterations");
  fire_max_force_ = h5::attr_double(f, "fire_max_force");
}

template void HopperRun<2>::save_checkpoint(const std::string&) const;
template void HopperRun<3>::save_checkpoint(const std::string&) const;
template void HopperRun<2>::load_checkpoint(const std::string&, bool);
template void HopperRun<3>::load_checkpoint(const std::string&, bool);

}  // namespace beverloo
