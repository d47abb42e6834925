#include "parameter_columns.h"

#include <set>
#include <string>

#include "engine/parameters.h"

namespace beverloo::db {
namespace {

// The runs view of schema 0003 (jobs' hand-written columns, results); the generated parameter
// columns are appended to it.
constexpr const char* kRunsJobColumns =
    "j.key, j.dir, j.state, j.engine_version, j.model, j.dimension, j.N, j.W_container, j.w, j.theta_w_left_deg, j.theta_w_right_deg, "
    "j.E_sp, j.E_w, j.zeta, j.mu, j.lambda, j.dissipation_scale, j.replica, j.seed, "
    "j.n_v, j.K_a, j.K_l, j.K_b, j.E_c";
constexpr const char* kRunsResultColumns =
    "r.status, r.Q, r.Q_err, r.Q_rel_err, r.window_start, r.window_end, r.exits_in_window, r.clogged, "
    "r.clog_time, r.rho_n, r.Q_prime, r.mean_F_drag, r.mean_F_friction, r.force_ratio, r.dt, r.wall_seconds";

std::set<std::string> jobs_columns(Database& db) {
  std::set<std::string> out;
  Statement st = db.prepare("SELECT name FROM pragma_table_xinfo('jobs')");
  while (st.step()) out.insert(st.get_text(0));
  return out;
}

}  // namespace

void sync_parameter_columns(Database& db) {
  const std::set<std::string> have = jobs_columns(db);
  std::string generated;
  bool added = false;
  for (const ParamSpec& p : job_parameters()) {
    if (p.sql_column.empty() || !p.omit_at_default) continue;  // the older ones are hand-written
    const std::string col(p.sql_column);
    generated += ", j." + col;
    if (have.count(col)) continue;
    std::string expr = "json_extract(job_json, '$." + std::string(p.path) + "')";
    if (!p.sql_default.empty()) expr = "coalesce(" + expr + ", " + std::string(p.sql_default) + ")";
    db.exec("ALTER TABLE jobs ADD COLUMN " + col + " " + std::string(p.sql_type()) + " GENERATED ALWAYS AS (" + expr +
            ") VIRTUAL");
    added = true;
  }
  const std::string view = std::string("CREATE VIEW runs AS SELECT ") + kRunsJobColumns + generated + ", " +
                           kRunsResultColumns + ", " + kT0PerCpuMinuteSql +
                           " AS t0_per_cpu_minute FROM jobs j LEFT JOIN results r ON r.job_key = j.key";
  // rebuilt when a column was added or the view is another binary's (a database made before the
  // view had engine_version or t0_per_cpu_minute, say): the view holds no data, so this loses nothing
  Statement current = db.prepare("SELECT coalesce(sql, '') FROM sqlite_master WHERE type = 'view' AND name = 'runs'");
  if (!added && current.step() && current.get_text(0) == view) return;
  current.reset();
  db.exec("DROP VIEW IF EXISTS runs");
  db.exec(view);
}

}  // namespace beverloo::db
