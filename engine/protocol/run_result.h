#pragma once
/// \file run_result.h
/// \brief Everything one hopper run reports (written to result.h5 and summary.json).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drain_fit.h"

namespace beverloo {

/// What a run's status means, in one phrase (report, `campaign status`, docs/database.md).
inline const char* run_status_meaning(const std::string& status) {
  if (status == "converged") return "Q reached run.target_rel_err";
  if (status == "time_limit") return "run.t_max came first: Q is stored with its (larger) error";
  if (status == "unreachable")
    return "stopped early (run.stop_unreachable): run.t_max could not reach the error target; Q is stored with its error";
  if (status == "clogged") return "the flow stopped: no exit for run.t_clog (Q = 0)";
  if (status == "interrupted") return "stopped by a signal; resumes from its checkpoint";
  if (status == "drained") return "a draining hopper emptied to drain.stop_below, or until only particles beside the orifice (a dead zone) remained; Q is c0 t0 of dN/dt = -c0 sqrt(N)";
  return "";
}

struct RunResult {
  // outcome
  std::string status;       ///< "converged" | "time_limit" | "unreachable" | "clogged" | "drained" | "interrupted"
  std::string stop_reason;  ///< one human sentence
  // flow rate (physics.md 7), area (2D) or volume (3D) per t0
  double Q = 0, Q_err = 0, Q_rel_err = 0;
  double window_start = 0, window_end = 0;
  std::int64_t exits_in_window = 0, exits_total = 0;
  bool clogged = false;
  double clog_time = -1;            ///< time of the last exit before the clog (-1: no clog)
  double clog_detected_time = -1;   ///< when t_clog without exits had passed
  // density and corrected flow rate
  double rho_n = 0, rho_n_err = 0, a_eff = 0, Q_prime = 0, Q_prime_err = 0;
  // dissipation forces
  double mean_F_drag = 0, mean_F_friction = 0, force_ratio = 0;  ///< ratio = drag / friction
  double force_ratio_err = NAN;  ///< its standard error (NaN: no friction, or under two blocks)
  // a draining hopper (reinject = false): Q and Q_err are c0 and its error (per t0) of the fit
  // dN/dt = -c0 sqrt(N), the window the span of its blocks
  bool draining = false;
  int n_initial = 0, n_remaining = 0;  ///< particles in the hopper at t = 0 and at the end
  DrainFit drain;
  // series
  std::vector<double> profile_h, profile_v_g, profile_v_g_err;
  double rate_bin = 0;
  std::vector<double> rate;  ///< binned exit rate from t = 0
  std::vector<double> exit_time, exit_size;
  std::vector<std::int64_t> exit_particle;
  // run statistics (not part of the physics result; differ between machines)
  double dt = 0;
  std::string dt_limiting_term;
  std::uint64_t seed = 0;
  std::int64_t steps = 0;
  double t_end = 0;
  std::int64_t fire_iterations = 0;
  double fire_max_force = 0;
  std::int64_t reinjections = 0, reinjection_fallbacks = 0;
  double max_overlap_seen = 0;
  double wall_seconds = 0, particle_steps_per_second = 0;
  std::int64_t neighbor_builds = 0;
  int resumed_times = 0;

  /// The scalar part (no long series) for summary.json and the campaign database.
  nlohmann::json summary_json() const;

 private:
  nlohmann::json flow_summary_json() const;
};

}  // namespace beverloo
