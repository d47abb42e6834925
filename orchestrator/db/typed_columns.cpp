#include "typed_columns.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "engine/config.h"
#include "engine/parameters.h"
#include "engine/protocol/result_fields.h"

namespace beverloo::db {
namespace {

// The runs view's first job columns, in the order schemas 0001 and 0003 gave them (a user's
// SELECT * keeps its column positions); the parameters added since are appended in table order.
constexpr const char* kRunsJobColumns =
    "j.key, j.dir, j.state, j.engine_version, j.model, j.dimension, j.N, j.W_container, j.w, j.theta_w_left_deg, j.theta_w_right_deg, "
    "j.E_sp, j.E_w, j.zeta, j.mu, j.lambda, j.dissipation_scale, j.replica, j.seed, "
    "j.n_v, j.K_a, j.K_l, j.K_b, j.E_c";

std::set<std::string> columns_of(Database& db, const char* table) {
  std::set<std::string> out;
  Statement st = db.prepare(std::string("SELECT name FROM pragma_table_xinfo('") + table + "')");
  while (st.step()) out.insert(st.get_text(0));
  return out;
}

bool stored(const ResultField& f) { return f.sql == ResultSql::Column; }

/// The one parameter whose jobs column is stored: the seed the run uses is a hash of the job
/// when the job gives none, so it cannot be read back from job_json (schema 0010).
bool stored_parameter(const ParamSpec& p) { return p.type == ParamType::Seed; }

/// The parameters whose columns schemas 0001 and 0003 created and the runs view lists by hand
/// (kRunsJobColumns); they are generated since 0010 like the rest, only their place in the view
/// is older.
bool in_runs_job_columns(const ParamSpec& p) { return !p.omit_at_default; }

/// The indexes over generated parameter columns: created with the columns (schema 0010 rebuilt
/// jobs without them). Named as schemas 0001 and 0003 named them.
constexpr const char* kJobsParameterIndexes[] = {
    "CREATE INDEX IF NOT EXISTS jobs_physics ON jobs (dimension, lambda, w)",
    "CREATE INDEX IF NOT EXISTS jobs_dp_shape ON jobs (K_l, K_b)",
};

/// "INSERT OR IGNORE INTO table (c1, c2, ...) VALUES (?1, ?2, ...)", the columns in bind order.
std::string insert_sql(const char* table, const std::vector<std::string>& columns) {
  std::string cols, values;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    cols += (i ? ", " : "") + columns[i];
    values += (i ? ", ?" : "?") + std::to_string(i + 1);
  }
  return std::string("INSERT OR IGNORE INTO ") + table + " (" + cols + ") VALUES (" + values + ")";
}

}  // namespace

const std::string& jobs_insert_sql() {
  static const std::string sql = [] {
    std::vector<std::string> cols = {"key", "dir", "job_json", "engine_version", "lambda", "dissipation_scale"};
    for (const ParamSpec& p : job_parameters())
      if (!p.sql_column.empty() && stored_parameter(p)) cols.emplace_back(p.sql_column);
    return insert_sql("jobs", cols);
  }();
  return sql;
}

void bind_parameter_columns(Statement& insert, const SimConfig& config) {
  int i = 6;
  for (const ParamSpec& p : job_parameters()) {
    if (p.sql_column.empty() || !stored_parameter(p)) continue;
    insert.bind(++i, static_cast<std::int64_t>(config.effective_seed()));
  }
}

const std::string& results_insert_sql() {
  static const std::string sql = [] {
    std::vector<std::string> cols = {"job_key", "attempt_id"};
    for (const ResultField& f : result_fields())
      if (stored(f)) cols.emplace_back(f.name);
    cols.emplace_back("summary_json");
    return insert_sql("results", cols);
  }();
  return sql;
}

void bind_result_columns(Statement& insert, const nlohmann::json& s, const std::string& summary_text) {
  const bool clogged = s.at("clogged").get<bool>();
  int i = 2;
  for (const ResultField& f : result_fields()) {
    if (!stored(f)) continue;
    ++i;
    const nlohmann::json& v = s.at(std::string(f.name));
    if (f.null_unless_clogged && !clogged) {
      insert.bind_null(i);
      continue;
    }
    switch (f.type) {
      case ResultType::Real: insert.bind(i, v.is_number() ? v.get<double>() : INFINITY); break;
      case ResultType::Integer: insert.bind(i, v.get<std::int64_t>()); break;
      case ResultType::Boolean: insert.bind(i, static_cast<std::int64_t>(v.get<bool>())); break;
      case ResultType::Text: insert.bind(i, v.get<std::string>()); break;
    }
  }
  insert.bind(i + 1, summary_text);
}

void sync_typed_columns(Database& db) {
  bool added = false;
  // parameters: every row with a column but the seed (schema 0010); a database that has not
  // reached 0010 cannot be open here (open_store migrates first)
  const std::set<std::string> have_jobs = columns_of(db, "jobs");
  std::string job_columns;
  for (const ParamSpec& p : job_parameters()) {
    if (p.sql_column.empty() || stored_parameter(p)) continue;
    const std::string col(p.sql_column);
    if (!in_runs_job_columns(p)) job_columns += ", j." + col;
    if (have_jobs.count(col)) continue;
    std::string expr = "json_extract(job_json, '$." + std::string(p.path) + "')";
    if (!p.sql_default.empty()) expr = "coalesce(" + expr + ", " + std::string(p.sql_default) + ")";
    db.exec("ALTER TABLE jobs ADD COLUMN " + col + " " + std::string(p.sql_type()) + " GENERATED ALWAYS AS (" + expr +
            ") VIRTUAL");
    added = true;
  }
  for (const char* index : kJobsParameterIndexes) db.exec(index);
  // results: every summary field that schema 0001 did not store
  const std::set<std::string> have_results = columns_of(db, "results");
  std::string result_columns;
  for (const ResultField& f : result_fields()) {
    if (f.in_runs_view) result_columns += std::string(result_columns.empty() ? "" : ", ") + "r." + std::string(f.name);
    if (f.sql != ResultSql::Generated || have_results.count(std::string(f.name))) continue;
    db.exec("ALTER TABLE results ADD COLUMN " + std::string(f.name) + " " + std::string(f.sql_type()) +
            " GENERATED ALWAYS AS (json_extract(summary_json, '$." + std::string(f.name) + "')) VIRTUAL");
    added = true;
  }
  const std::string view = std::string("CREATE VIEW runs AS SELECT ") + kRunsJobColumns + job_columns + ", " +
                           result_columns + ", " + kT0PerCpuMinuteSql +
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
