#include "result_file.h"
#include "core/atomic_file.h"

#include "../parameters.h"

#include "h5.h"

namespace beverloo {

void write_result_file(const std::string& path, const SimConfig& c, const RunResult& r) {
  PendingFile file(path);  // removed if anything below fails (a full disk)
  {
    H5Handle f = h5::create_file(file.path());
    h5::attr(f, "format", std::string("beverloo-result"));
    h5::attr(f, "format_version", std::int64_t{1});
    h5::attr(f, "engine_version", std::string(BEVERLOO_VERSION));
    {
      H5Handle p = h5::create_group(f, "parameters");
      h5::attr(p, "job_json", c.to_json().dump());
      h5::attr(p, "dimension", std::int64_t{c.dimension});
      h5::attr(p, "N", std::int64_t{c.N});
      h5::attr(p, "W", c.W);
      h5::attr(p, "w", c.w);
      h5::attr(p, "theta_w_left_deg", c.theta_w_left_deg);
      h5::attr(p, "theta_w_right_deg", c.theta_w_right_deg);
      h5::attr(p, "E_sp", c.E_sp);
      h5::attr(p, "E_w", c.E_w);
      h5::attr(p, "zeta", c.zeta);
      h5::attr(p, "mu", c.mu);
      h5::attr(p, "lambda", derived::lambda(c).value_or(INFINITY));  // docs/sweeps.md
      // the authors' model options (physics.md 10), written only where a job uses them
      if (c.mu_n) h5::attr(p, "mu_n", *c.mu_n);
      if (c.mu_t) h5::attr(p, "mu_t", *c.mu_t);
      if (c.drag_rate > 0) h5::attr(p, "drag_rate", c.drag_rate);
      h5::attr(p, "seed", static_cast<std::int64_t>(r.seed));
      h5::attr(p, "dt", r.dt);
    }
    {
      H5Handle g = h5::create_group(f, "result");
      h5::attr(g, "status", r.status);
      h5::attr(g, "stop_reason", r.stop_reason);
      h5::attr(g, "Q", r.Q);
      h5::attr(g, "Q_err", r.Q_err);
      h5::attr(g, "Q_rel_err", r.Q_rel_err);
      h5::attr(g, "window_start", r.window_start);
      h5::attr(g, "window_end", r.window_end);
      h5::attr(g, "exits_in_window", r.exits_in_window);
      h5::attr(g, "exits_total", r.exits_total);
      h5::attr(g, "clogged", std::int64_t{r.clogged});
      h5::attr(g, "clog_time", r.clog_time);
      h5::attr(g, "clog_detected_time", r.clog_detected_time);
      h5::attr(g, "rho_n", r.rho_n);
      h5::attr(g, "rho_n_err", r.rho_n_err);
      h5::attr(g, "a_eff", r.a_eff);
      h5::attr(g, "Q_prime", r.Q_prime);
      h5::attr(g, "Q_prime_err", r.Q_prime_err);
      h5::attr(g, "mean_F_drag", r.mean_F_drag);
      h5::attr(g, "mean_F_friction", r.mean_F_friction);
      h5::attr(g, "force_ratio", r.force_ratio);
      h5::attr(g, "max_overlap_seen", r.max_overlap_seen);
    }
    {
      H5Handle g = h5::create_group(f, "exits");
      h5::write(g, "time", r.exit_time);
      h5::write(g, "size", r.exit_size);
      h5::write(g, "particle", r.exit_particle);
    }
    if (r.draining) {  // only then: a continuous run's file keeps its layout
      H5Handle g = h5::create_group(f, "drain");
      h5::attr(g, "n_initial", std::int64_t{r.n_initial});
      h5::attr(g, "n_remaining", std::int64_t{r.n_remaining});
      h5::attr(g, "fit_ok", std::int64_t{r.drain.ok});
      h5::attr(g, "fit_message", r.drain.message);
      h5::attr(g, "c0", r.drain.c0);
      h5::attr(g, "c0_err", r.drain.c0_err);
      h5::attr(g, "chi2_red", r.drain.chi2_red);
      h5::attr(g, "exits_used", std::int64_t{r.drain.exits_used});
      // N(t): the hopper's count just after each exit, and the fitted blocks
      std::vector<double> n_after(r.exit_time.size());
      for (std::size_t k = 0; k < n_after.size(); ++k) n_after[k] = double(r.n_initial) - double(k) - 1;
      h5::write(g, "N_after_exit", n_after);
      h5::write(g, "block_N", r.drain.block_N);
      h5::write(g, "block_rate", r.drain.block_rate);
      h5::write(g, "block_rate_err", r.drain.block_rate_err);
    }
    {
      H5Handle g = h5::create_group(f, "rate");
      h5::attr(g, "bin_width", r.rate_bin);
      h5::write(g, "value", r.rate);
    }
    {
      H5Handle g = h5::create_group(f, "profile");
      h5::write(g, "h", r.profile_h);
      h5::write(g, "v_g", r.profile_v_g);
      h5::write(g, "v_g_err", r.profile_v_g_err);
    }
    {
      H5Handle g = h5::create_group(f, "clog_events");
      std::vector<double> times, detected;
      if (r.clogged) {
        times.push_back(r.clog_time);
        detected.push_back(r.clog_detected_time);
      }
      h5::write(g, "time", times);
      h5::write(g, "detected_time", detected);
    }
    {
      H5Handle g = h5::create_group(f, "run");
      h5::attr(g, "steps", r.steps);
      h5::attr(g, "t_end", r.t_end);
      h5::attr(g, "dt_limiting_term", r.dt_limiting_term);
      h5::attr(g, "fire_iterations", r.fire_iterations);
      h5::attr(g, "fire_max_force", r.fire_max_force);
      h5::attr(g, "reinjections", r.reinjections);
      h5::attr(g, "reinjection_fallbacks", r.reinjection_fallbacks);
      h5::attr(g, "wall_seconds", r.wall_seconds);
      h5::attr(g, "particle_steps_per_second", r.particle_steps_per_second);
      h5::attr(g, "neighbor_builds", r.neighbor_builds);
      h5::attr(g, "resumed_times", std::int64_t{r.resumed_times});
    }
    H5Fflush(f, H5F_SCOPE_GLOBAL);
  }
  file.commit();
}

}  // namespace beverloo
