// The result-field table (engine/protocol/result_fields): every row reaches each place it names
// (summary.json, result.h5's groups, the results table's stored and generated columns, the runs
// view) with its value, and nothing else is written there; schema 0001's results columns are
// exactly the rows stored by the store; docs/database.md shows the generated table. And the
// jobs table's parameter columns: each one a row of the parameter table, filled by its accessor.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/config.h"
#include "engine/io/h5.h"
#include "engine/io/result_file.h"
#include "engine/parameters.h"
#include "engine/protocol/result_fields.h"
#include "engine/protocol/run_result.h"
#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"

namespace beverloo {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

/// A result whose every scalar field has a value of its own (none at its default), so that a
/// field written from the wrong member, or not at all, shows.
RunResult distinct_result() {
  RunResult r;
  r.status = "clogged";
  r.stop_reason = "no exit for 20 t0";
  r.Q = 1.25;
  r.Q_err = 0.0625;
  r.Q_rel_err = 0.05;
  r.window_start = 12.5;
  r.window_end = 87.25;
  r.exits_in_window = 321;
  r.exits_total = 400;
  r.clogged = true;
  r.clog_time = 90.5;
  r.clog_detected_time = 110.5;
  r.rho_n = 1.0625;
  r.rho_n_err = 0.03125;
  r.a_eff = 0.94;
  r.Q_prime = 1.5;
  r.Q_prime_err = 0.125;
  r.mean_F_drag = 0.375;
  r.mean_F_friction = 0.1875;
  r.force_ratio = 2.0;
  r.force_ratio_err = 0.015625;
  r.max_overlap_seen = 0.0123;
  r.dt = 1.25e-3;
  r.seed = 987654321;
  r.steps = 96400;
  r.t_end = 120.5;
  r.dt_limiting_term = "sp_contact";
  r.fire_iterations = 77;
  r.fire_max_force = 3.5e-5;
  r.reinjections = 55;
  r.reinjection_fallbacks = 6;
  r.wall_seconds = 4.5;
  r.particle_steps_per_second = 2.5e7;
  r.neighbor_builds = 1234;
  r.resumed_times = 3;
  return r;
}

double as_double(const ResultValue& v) {
  return std::visit(
      [](const auto& x) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::string>)
          return NAN;
        else
          return static_cast<double>(x);
      },
      v);
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("beverloo-fields-" + new_token());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

herr_t collect_name(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::set<std::string>*>(out)->insert(name);
  return 0;
}

std::set<std::string> attribute_names(hid_t group) {
  std::set<std::string> names;
  H5Aiterate2(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &names);
  return names;
}

TEST(ResultFields, NamesAreUniqueAndEveryRowHasAGetter) {
  std::set<std::string> names;
  for (const ResultField& f : result_fields()) {
    EXPECT_TRUE(names.insert(std::string(f.name)).second) << f.name << " twice";
    EXPECT_NE(f.get, nullptr) << f.name;
    EXPECT_FALSE(f.doc.empty()) << f.name;
    if (f.sql != ResultSql::None) {
      EXPECT_TRUE(f.in_summary) << f.name << ": the store reads its columns from summary.json";
    }
    if (f.in_runs_view) {
      EXPECT_NE(f.sql, ResultSql::None) << f.name;
    }
  }
  EXPECT_EQ(find_result_field("mean_F_friction"), &result_fields()[18]);
  EXPECT_EQ(find_result_field("no_such_field"), nullptr);
}

TEST(ResultFields, SummaryJsonHasEveryRowMarkedForItAndNothingElse) {
  const RunResult r = distinct_result();
  const json s = r.summary_json();
  std::set<std::string> expected;
  for (const ResultField& f : result_fields()) {
    if (!f.in_summary) continue;
    expected.insert(std::string(f.name));
    const json& v = s.at(std::string(f.name));
    if (f.type == ResultType::Text)
      EXPECT_EQ(v.get<std::string>(), std::get<std::string>(f.get(r))) << f.name;
    else if (f.type == ResultType::Boolean)
      EXPECT_EQ(v.get<bool>(), std::get<bool>(f.get(r))) << f.name;
    else
      EXPECT_EQ(v.get<double>(), as_double(f.get(r))) << f.name;
  }
  std::set<std::string> keys;
  for (auto it = s.begin(); it != s.end(); ++it) keys.insert(it.key());
  EXPECT_EQ(keys, expected);
  // each row reads its own member: the summary is the result above, written out by hand
  const json expected_summary = {
      {"status", "clogged"}, {"stop_reason", "no exit for 20 t0"}, {"Q", 1.25}, {"Q_err", 0.0625},
      {"Q_rel_err", 0.05}, {"window_start", 12.5}, {"window_end", 87.25}, {"exits_in_window", 321},
      {"exits_total", 400}, {"clogged", true}, {"clog_time", 90.5}, {"clog_detected_time", 110.5},
      {"rho_n", 1.0625}, {"rho_n_err", 0.03125}, {"a_eff", 0.94}, {"Q_prime", 1.5}, {"Q_prime_err", 0.125},
      {"mean_F_drag", 0.375}, {"mean_F_friction", 0.1875}, {"force_ratio", 2.0}, {"force_ratio_err", 0.015625},
      {"max_overlap_seen", 0.0123},
      {"dt", 1.25e-3}, {"seed", 987654321u}, {"steps", 96400}, {"t_end", 120.5}, {"dt_limiting_term", "sp_contact"},
      {"fire_iterations", 77}, {"reinjections", 55}, {"reinjection_fallbacks", 6}, {"wall_seconds", 4.5},
      {"particle_steps_per_second", 2.5e7}, {"resumed_times", 3}};
  EXPECT_EQ(s, expected_summary);
  // and the two rows only result.h5 has
  EXPECT_EQ(as_double(find_result_field("fire_max_force")->get(r)), 3.5e-5);
  EXPECT_EQ(as_double(find_result_field("neighbor_builds")->get(r)), 1234);
}

TEST(ResultFields, ResultFileGroupsHoldTheirRows) {
  TempDir dir;
  SimConfig c = SimConfig::from_json(json{{"N", 50}, {"W", 12}, {"w", 4}, {"zeta", 0.3}, {"mu", 0.0}});
  c.resolve_and_validate();
  const RunResult r = distinct_result();
  const std::string path = (dir.path / "result.h5").string();
  write_result_file(path, c, r);
  H5Handle file = h5::open_file(path);
  for (const auto& [group, which] : {std::pair{"result", ResultGroup::Result}, std::pair{"run", ResultGroup::Run}}) {
    H5Handle g = h5::open_group(file, group);
    std::set<std::string> expected;
    for (const ResultField& f : result_fields()) {
      if (f.h5_group != which) continue;
      expected.insert(std::string(f.name));
      const std::string name(f.name);
      if (f.type == ResultType::Text)
        EXPECT_EQ(h5::attr_string(g, name), std::get<std::string>(f.get(r))) << group << "@" << name;
      else if (f.type == ResultType::Real)
        EXPECT_EQ(h5::attr_double(g, name), as_double(f.get(r))) << group << "@" << name;
      else
        EXPECT_EQ(h5::attr_int64(g, name), static_cast<std::int64_t>(as_double(f.get(r)))) << group << "@" << name;
    }
    EXPECT_EQ(attribute_names(g), expected) << "/" << group;
  }
}

TEST(ResultFields, ParametersGroupHoldsEveryRowOfTheParameterTable) {
  // one job per model family: the rows that apply to it, each as the job has it, and no other
  for (const json& job :
       {json{{"N", 50}, {"W", 12}, {"w", 4}, {"zeta", 0.3}, {"mu", 0.5}, {"mu_n", 0.1}},
        json{{"model", "dp_smooth"}, {"N", 20}, {"W", 10}, {"w", 4}, {"zeta", 0}, {"mu", 0}, {"drag_rate", 1.5},
             {"dp", {{"K_l", 88.0}, {"K_l_large", 120.0}}}, {"run", {{"t_max", 42}}}}}) {
    TempDir dir;
    SimConfig c = SimConfig::from_json(job);
    c.resolve_and_validate();
    const RunResult r = distinct_result();
    const std::string path = (dir.path / "result.h5").string();
    write_result_file(path, c, r);
    H5Handle file = h5::open_file(path);
    H5Handle p = h5::open_group(file, "parameters");
    std::set<std::string> expected{"job_json", "lambda"};
    SimConfig m = c;
    for (const ParamSpec& row : job_parameters()) {
      if (!parameter_applies(row.models, c.model) || row.path == "theta_w_deg") continue;
      const std::string name(row.path);
      const ParamAccess& a = row.access;
      switch (row.type) {
        case ParamType::Real: EXPECT_EQ(h5::attr_double(p, name), a.real(m)) << name; break;
        case ParamType::OptionalReal:
          if (!a.optional_real(m)) continue;  // unset: not written
          EXPECT_EQ(h5::attr_double(p, name), *a.optional_real(m)) << name;
          break;
        case ParamType::Integer: EXPECT_EQ(h5::attr_int64(p, name), a.integer(m)) << name; break;
        case ParamType::Integer64: EXPECT_EQ(h5::attr_int64(p, name), a.integer64(m)) << name; break;
        case ParamType::Boolean: EXPECT_EQ(h5::attr_int64(p, name), a.boolean(m) ? 1 : 0) << name; break;
        case ParamType::Text: EXPECT_EQ(h5::attr_string(p, name), a.text(m)) << name; break;
        case ParamType::RealOrAuto: EXPECT_EQ(h5::attr_double(p, name), r.dt) << name; break;
        case ParamType::Seed: EXPECT_EQ(h5::attr_int64(p, name), static_cast<std::int64_t>(r.seed)) << name; break;
      }
      expected.insert(name);
    }
    EXPECT_EQ(attribute_names(p), expected) << c.model;
    EXPECT_EQ(h5::attr_string(p, "job_json"), c.to_json().dump());
    EXPECT_TRUE(expected.count(c.model == "sp" ? "mu_n" : "dp.K_l_large")) << c.model;
    EXPECT_EQ(h5::attr_double(p, "lambda"), derived::lambda(c).value_or(INFINITY));
  }
}

/// A migrated store in a temporary directory with one campaign of two jobs.
struct Store {
  TempDir dir;
  db::Database db{(dir.path / "campaign.sqlite").string(), db::Database::Mode::ReadWrite};
  CampaignStore store{db};
  std::int64_t campaign = -1;
  Store() {
    db::open_store(db);
    const json sweep = {{"base", {{"N", 50}, {"W", 12}, {"zeta", 0.3}, {"mu", 0.0}}}, {"sweep", {{"w", {3, 4}}}}};
    const Sweep s = Sweep::parse(sweep, "test");
    campaign = store.create_campaign(s, sweep.dump(), s.expand());
  }
};

TEST(ResultFields, StoredColumnsAreSchema0001sAndTheOthersAreGenerated) {
  Store st;
  std::set<std::string> plain, generated;
  db::Statement cols = st.db.prepare("SELECT name, hidden FROM pragma_table_xinfo('results')");
  while (cols.step()) (cols.get_int(1) == 0 ? plain : generated).insert(cols.get_text(0));
  std::set<std::string> expected_plain = {"job_key", "attempt_id", "summary_json", "ingested_at"}, expected_generated;
  for (const ResultField& f : result_fields()) {
    if (f.sql == ResultSql::Column) expected_plain.insert(std::string(f.name));
    if (f.sql == ResultSql::Generated) expected_generated.insert(std::string(f.name));
  }
  EXPECT_EQ(plain, expected_plain) << "a Column row must be a column of schema 0001's results table";
  EXPECT_EQ(generated, expected_generated);
  // the runs view's result columns are the rows marked for it
  std::set<std::string> view;
  db::Statement v = st.db.prepare("SELECT name FROM pragma_table_info('runs')");
  while (v.step()) view.insert(v.get_text(0));
  for (const ResultField& f : result_fields())
    if (f.in_runs_view) {
      EXPECT_TRUE(view.count(std::string(f.name))) << f.name << " missing from the runs view";
    }
  EXPECT_TRUE(view.count("t0_per_cpu_minute"));
}

TEST(ResultFields, IngestedResultReadsBackFromEveryColumn) {
  Store st;
  RunResult clogged = distinct_result();
  RunResult flowing = distinct_result();
  flowing.status = "converged";
  flowing.clogged = false;
  flowing.clog_time = -1;
  flowing.force_ratio = INFINITY;  // no friction: summary.json holds null, the database +inf
  std::vector<std::string> keys;
  for (const RunResult* r : {&clogged, &flowing}) {
    auto job = st.store.claim_next(st.campaign, "local", "host");
    ASSERT_TRUE(job);
    keys.push_back(job->key);
    st.store.ingest_success(*job, r->summary_json().dump(), {0.5}, {1.0}, {0.1});
  }
  for (std::size_t n = 0; n < keys.size(); ++n) {
    const RunResult& r = n == 0 ? clogged : flowing;
    for (const ResultField& f : result_fields()) {
      if (f.sql == ResultSql::None) continue;
      db::Statement q = st.db.prepare("SELECT " + std::string(f.name) + " FROM results WHERE job_key = ?1");
      q.bind(1, keys[n]);
      ASSERT_TRUE(q.step());
      const std::string what = std::string(f.name) + (n == 0 ? " (clogged)" : " (flowing)");
      if (f.null_unless_clogged && !r.clogged) {
        EXPECT_TRUE(q.is_null(0)) << what;
        continue;
      }
      ASSERT_FALSE(q.is_null(0)) << what;
      if (f.type == ResultType::Text)
        EXPECT_EQ(q.get_text(0), std::get<std::string>(f.get(r))) << what;
      else if (f.type == ResultType::Real && f.sql == ResultSql::Column)
        EXPECT_EQ(q.get_double(0), as_double(f.get(r))) << what;  // +inf stays +inf
      else if (f.type == ResultType::Real)
        EXPECT_DOUBLE_EQ(q.get_double(0), as_double(f.get(r))) << what;  // through JSON text
      else
        EXPECT_EQ(q.get_int(0), static_cast<std::int64_t>(as_double(f.get(r)))) << what;
    }
  }
  // the runs view shows a result column with its value
  db::Statement q = st.db.prepare("SELECT mean_F_friction, clog_time FROM runs WHERE key = ?1");
  q.bind(1, keys[0]);
  ASSERT_TRUE(q.step());
  EXPECT_EQ(q.get_double(0), 0.1875);
  EXPECT_EQ(q.get_double(1), 90.5);
}

TEST(TypedColumns, JobsColumnsAreParameterRowsAndTheFewThatAreNot) {
  Store st;
  std::set<std::string> plain, generated;
  db::Statement cols = st.db.prepare("SELECT name, hidden FROM pragma_table_xinfo('jobs')");
  while (cols.step()) (cols.get_int(1) == 0 ? plain : generated).insert(cols.get_text(0));
  // stored: what is not a parameter (identity, derived dissipation, bookkeeping) and the seed
  // (derived when the job gives none); every other parameter column is generated (schema 0010)
  std::set<std::string> expected_plain = {"key", "dir", "job_json", "engine_version", "lambda", "dissipation_scale",
                                          "seed", "state", "retries_used", "created_at"},
                        expected_generated;
  for (const ParamSpec& p : job_parameters())
    if (!p.sql_column.empty() && p.sql_column != "seed") expected_generated.insert(std::string(p.sql_column));
  EXPECT_EQ(plain, expected_plain);
  EXPECT_EQ(generated, expected_generated);
  // each generated column has its row's SQL type, and the indexes over them exist
  for (const ParamSpec& p : job_parameters()) {
    if (p.sql_column.empty()) continue;
    db::Statement t = st.db.prepare("SELECT type FROM pragma_table_xinfo('jobs') WHERE name = ?1");
    t.bind(1, std::string(p.sql_column));
    ASSERT_TRUE(t.step()) << p.sql_column;
    EXPECT_EQ(t.get_text(0), p.sql_type()) << p.sql_column;
  }
  EXPECT_EQ(st.db.scalar_int("SELECT count(*) FROM sqlite_master WHERE type = 'index' AND name IN "
                             "('jobs_state', 'jobs_physics', 'jobs_dp_shape')"),
            3);
  // an SP and a DP job: the columns hold the resolved values (the DP ones NULL for SP, E_sp NULL
  // for DP: neither job carries the other model's fields), the seed the one the run uses
  const json sweep = {{"base", {{"N", 40}, {"W", 10}, {"zeta", 0.3}, {"mu", 0.0}}},
                      {"sweep", {{"model", {"sp", "dp_smooth"}}, {"w", {4}}}}};
  const Sweep s = Sweep::parse(sweep, "test");
  const std::vector<JobSpec> jobs = s.expand();
  st.store.create_campaign(s, sweep.dump(), jobs);
  for (const JobSpec& j : jobs) {
    db::Statement q = st.db.prepare("SELECT model, N, W_container, E_sp, E_w, K_l, E_c, seed, replica, t_max FROM jobs WHERE key = ?1");
    q.bind(1, j.key);
    ASSERT_TRUE(q.step());
    const SimConfig& c = j.config;
    EXPECT_EQ(q.get_text(0), c.model);
    EXPECT_EQ(q.get_int(1), c.N);
    EXPECT_EQ(q.get_double(2), c.W);
    EXPECT_EQ(q.get_double(4), c.E_w);
    if (c.is_dp()) {
      EXPECT_TRUE(q.is_null(3));
      EXPECT_EQ(q.get_double(5), c.dp.K_l);
      EXPECT_EQ(q.get_double(6), c.dp.E_c);
    } else {
      EXPECT_EQ(q.get_double(3), c.E_sp);
      EXPECT_TRUE(q.is_null(5));
      EXPECT_TRUE(q.is_null(6));
    }
    EXPECT_EQ(static_cast<std::uint64_t>(q.get_int(7)), c.effective_seed());
    EXPECT_EQ(q.get_int(8), c.replica);
    EXPECT_EQ(q.get_double(9), c.run.t_max);
  }
}

TEST(ResultFields, DocsDatabaseShowsTheGeneratedTable) {
  std::ifstream in(BEVERLOO_SOURCE_DIR "/docs/database.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::string begin = "<!-- results:begin (generated: beverloo params --results --format markdown) -->\n";
  const std::string end = "<!-- results:end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), result_fields_markdown())
      << "docs/database.md is out of date: run scripts/regen-params.sh";
}

}  // namespace
}  // namespace beverloo
