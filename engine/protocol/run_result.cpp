#include "run_result.h"

namespace beverloo {

nlohmann::json RunResult::flow_summary_json() const {
  return {{"status", status},
          {"stop_reason", stop_reason},
          {"Q", Q},
          {"Q_err", Q_err},
          {"Q_rel_err", Q_rel_err},
          {"window_start", window_start},
          {"window_end", window_end},
          {"exits_in_window", exits_in_window},
          {"exits_total", exits_total},
          {"clogged", clogged},
          {"clog_time", clog_time},
          {"clog_detected_time", clog_detected_time},
          {"rho_n", rho_n},
          {"rho_n_err", rho_n_err},
          {"a_eff", a_eff},
          {"Q_prime", Q_prime},
          {"Q_prime_err", Q_prime_err},
          {"mean_F_drag", mean_F_drag},
          {"mean_F_friction", mean_F_friction},
          {"force_ratio", force_ratio},
          {"dt", dt},
          {"dt_limiting_term", dt_limiting_term},
          {"seed", seed},
          {"steps", steps},
          {"t_end", t_end},
          {"fire_iterations", fire_iterations},
          {"reinjections", reinjections},
          {"reinjection_fallbacks", reinjection_fallbacks},
          {"max_overlap_seen", max_overlap_seen},
          {"wall_seconds", wall_seconds},
          {"particle_steps_per_second", particle_steps_per_second},
          {"resumed_times", resumed_times}};
}

nlohmann::json RunResult::summary_json() const {
  nlohmann::json j = flow_summary_json();
  if (draining)  // only then: a continuous run's summary stays as it was
    j["drain"] = {{"n_initial", n_initial}, {"n_remaining", n_remaining}, {"fit_ok", drain.ok},
                  {"fit_message", drain.message}, {"c0", drain.c0}, {"c0_err", drain.c0_err},
                  {"chi2_red", drain.chi2_red}, {"blocks", drain.blocks}, {"exits_used", drain.exits_used}};
  return j;
}

}  // namespace beverloo
