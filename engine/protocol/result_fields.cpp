#include "result_fields.h"

#include <sstream>

#include "run_result.h"

namespace beverloo {
namespace {

using T = ResultType;
using G = ResultGroup;
using S = ResultSql;

// A row's getter: the member as a ResultValue (int counters widened to int64).
#define BEVERLOO_FIELD(member) [](const RunResult& r) -> ResultValue { return r.member; }
#define BEVERLOO_FIELD64(member) [](const RunResult& r) -> ResultValue { return std::int64_t{r.member}; }

// The order is docs/database.md's. Within each result.h5 group it is also the order of that
// group's attributes, and the runs view's result columns come in this order.
const std::vector<ResultField> kFields = {
    // outcome
    {"status", T::Text, "-", "converged, time_limit, unreachable, clogged, drained (run_status_meaning)", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(status)},
    {"stop_reason", T::Text, "-", "why the run ended, one sentence", G::Result, true, S::Generated, false, false,
     BEVERLOO_FIELD(stop_reason)},
    // flow rate
    {"Q", T::Real, "sigma_avg^d/t0",
     "flow rate: exits' area (2D) or volume (3D) per t0 in the window; a draining hopper's c0 (per t0)", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(Q)},
    {"Q_err", T::Real, "sigma_avg^d/t0", "standard error of Q (blocking of the window's exits)", G::Result, true, S::Column,
     true, false, BEVERLOO_FIELD(Q_err)},
    {"Q_rel_err", T::Real, "-", "Q_err / Q", G::Result, true, S::Column, true, false, BEVERLOO_FIELD(Q_rel_err)},
    {"window_start", T::Real, "t0", "start of the measuring window (after the transient)", G::Result, true, S::Column,
     true, false, BEVERLOO_FIELD(window_start)},
    {"window_end", T::Real, "t0", "end of the measuring window", G::Result, true, S::Column, true, false,
     BEVERLOO_FIELD(window_end)},
    {"exits_in_window", T::Integer, "-", "particles that left through the orifice in the window", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(exits_in_window)},
    {"exits_total", T::Integer, "-", "particles that left through the orifice in the whole run", G::Result, true,
     S::Column, false, false, BEVERLOO_FIELD(exits_total)},
    // clogging
    {"clogged", T::Boolean, "-", "the flow stopped (no exit for run.t_clog); 0/1 in result.h5 and SQL", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(clogged)},
    {"clog_time", T::Real, "t0", "last exit before the clog (files: -1 without a clog; SQL: NULL)", G::Result, true,
     S::Column, true, true, BEVERLOO_FIELD(clog_time)},
    {"clog_detected_time", T::Real, "t0", "when run.t_clog without an exit had passed (-1 without a clog)", G::Result,
     true, S::Generated, false, false, BEVERLOO_FIELD(clog_detected_time)},
    // density and corrected flow rate (paper Appendix B)
    {"rho_n", T::Real, "1/sigma_avg^d",
     "number density in the 2w x w box above the orifice (3D: the cylinder of diameter 2w, height w)", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(rho_n)},
    {"rho_n_err", T::Real, "1/sigma_avg^d", "standard error of rho_n over time blocks", G::Result, true, S::Generated,
     false, false, BEVERLOO_FIELD(rho_n_err)},
    {"a_eff", T::Real, "sigma_avg^d", "effective area (volume) per particle, 1/rho_n", G::Result, true, S::Column, false,
     false, BEVERLOO_FIELD(a_eff)},
    {"Q_prime", T::Real, "sigma_avg^d/t0", "Appendix B's corrected flow rate Q a_eff / a_avg", G::Result, true, S::Column,
     true, false, BEVERLOO_FIELD(Q_prime)},
    {"Q_prime_err", T::Real, "sigma_avg^d/t0", "standard error of Q_prime", G::Result, true, S::Column, false, false,
     BEVERLOO_FIELD(Q_prime_err)},
    // dissipation forces
    {"mean_F_drag", T::Real, "rho sigma_avg^d g", "mean |F^zeta| per particle in the window", G::Result, true, S::Column,
     true, false, BEVERLOO_FIELD(mean_F_drag)},
    {"mean_F_friction", T::Real, "rho sigma_avg^d g", "mean |F^mu| per particle in the window", G::Result, true,
     S::Column, true, false, BEVERLOO_FIELD(mean_F_friction)},
    {"force_ratio", T::Real, "-", "mean_F_drag / mean_F_friction (inf without friction)",
     G::Result, true, S::Column, true, false, BEVERLOO_FIELD(force_ratio)},
    {"force_ratio_err", T::Real, "-",
     "standard error of force_ratio over time blocks of the window (delta method, blocked in pairs); none without friction",
     G::Result, true, S::Generated, true, false, BEVERLOO_FIELD(force_ratio_err)},
    {"max_overlap_seen", T::Real, "-", "largest relative contact overlap of the run, 1 - r/sigma_mn (DP: 1 - d/delta_mn)", G::Result, true, S::Generated,
     false, false, BEVERLOO_FIELD(max_overlap_seen)},
    // the step (in result.h5's /parameters)
    {"dt", T::Real, "t0", "the time step the run used", G::None, true, S::Column, true, false, BEVERLOO_FIELD(dt)},
    {"seed", T::Integer, "-", "the random seed the run used (the jobs table has it too)", G::None, true, S::None, false,
     false, BEVERLOO_FIELD(seed)},
    // run statistics: differ between machines, not part of the physics result
    {"steps", T::Integer, "-", "time steps taken", G::Run, true, S::Column, false, false, BEVERLOO_FIELD(steps)},
    {"t_end", T::Real, "t0", "simulated time at the end", G::Run, true, S::Generated, false, false, BEVERLOO_FIELD(t_end)},
    {"dt_limiting_term", T::Text, "-", "the force term whose time scale set dt \"auto\"", G::Run, true, S::Generated,
     false, false, BEVERLOO_FIELD(dt_limiting_term)},
    {"fire_iterations", T::Integer, "-", "FIRE iterations of the initial relaxation", G::Run, true, S::Generated, false,
     false, BEVERLOO_FIELD(fire_iterations)},
    {"fire_max_force", T::Real, "rho sigma_avg^d g", "largest force left after the relaxation", G::Run, false, S::None,
     false, false, BEVERLOO_FIELD(fire_max_force)},
    {"reinjections", T::Integer, "-", "particles put back on top", G::Run, true, S::Generated, false, false,
     BEVERLOO_FIELD(reinjections)},
    {"reinjection_fallbacks", T::Integer, "-", "reinjections that found no free place by the rule and used the fallback",
     G::Run, true, S::Generated, false, false, BEVERLOO_FIELD(reinjection_fallbacks)},
    {"wall_seconds", T::Real, "s", "engine wall time, summed over the sessions of a resumed run", G::Run, true, S::Column, true, false,
     BEVERLOO_FIELD(wall_seconds)},
    {"particle_steps_per_second", T::Real, "1/s", "particles (DP: vertices) times steps per wall second, of the last session (since a resume)", G::Run, true,
     S::Column, false, false, BEVERLOO_FIELD(particle_steps_per_second)},
    {"neighbor_builds", T::Integer, "-", "neighbour-list rebuilds", G::Run, false, S::None, false, false,
     BEVERLOO_FIELD(neighbor_builds)},
    {"resumed_times", T::Integer, "-", "times the run was resumed from a checkpoint", G::Run, true, S::Generated, false,
     false, BEVERLOO_FIELD64(resumed_times)},
};

#undef BEVERLOO_FIELD
#undef BEVERLOO_FIELD64

}  // namespace

std::string_view ResultField::sql_type() const {
  switch (type) {
    case ResultType::Real: return "REAL";
    case ResultType::Integer:
    case ResultType::Boolean: return "INTEGER";
    case ResultType::Text: return "TEXT";
  }
  return "TEXT";
}

std::string_view h5_group_name(ResultGroup g) {
  return g == ResultGroup::Result ? "/result" : g == ResultGroup::Run ? "/run" : "";
}

std::string_view sql_kind_name(ResultSql s) {
  return s == ResultSql::Column ? "column" : s == ResultSql::Generated ? "generated" : "";
}

const std::vector<ResultField>& result_fields() { return kFields; }

const ResultField* find_result_field(std::string_view name) {
  for (const ResultField& f : kFields)
    if (f.name == name) return &f;
  return nullptr;
}

std::string result_fields_markdown() {
  std::ostringstream md;
  md << "| field | unit | result.h5 | summary.json | SQL (`results`) | `runs` view | meaning |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const ResultField& f : kFields) {
    const std::string_view group = h5_group_name(f.h5_group);
    md << "| `" << f.name << "` | " << f.unit << " | " << (group.empty() ? "" : "`" + std::string(group) + "`") << " | "
       << (f.in_summary ? "yes" : "") << " | " << sql_kind_name(f.sql)
       << " | " << (f.in_runs_view ? "yes" : "") << " | " << f.doc << " |\n";
  }
  return md.str();
}

}  // namespace beverloo
