// The one table of job parameters (engine/parameters) and everything that comes from it: the
// JSON Schema's parameter definitions, docs/job-file.md, the SQL columns `query` users see.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/config.h"
#include "engine/parameters.h"
#include "engine/units.h"
#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"
#include "orchestrator/sweep/sweep_schema.h"

namespace beverloo {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ParameterTable, TheJsonSchemaHoldsTheTablesDefinitions) {
  const json schema = json::parse(read(BEVERLOO_SOURCE_DIR "/schema/sweep.schema.json"));
  const json defs = parameter_schema_defs();
  for (auto it = defs.begin(); it != defs.end(); ++it)
    EXPECT_EQ(schema["$defs"][it.key()], it.value())
        << "schema/sweep.schema.json $defs." << it.key()
        << " differs from the parameter table: regenerate it from `beverloo params --format schema-defs`";
}

TEST(ParameterTable, DocsJobFileShowsTheGeneratedTable) {
  const std::string doc = read(BEVERLOO_SOURCE_DIR "/docs/job-file.md");
  const std::string begin = "<!-- parameters:begin (generated: beverloo params --format markdown) -->\n";
  const std::string end = "<!-- parameters:end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), parameters_markdown())
      << "docs/job-file.md is out of date: paste `beverloo params --format markdown` between the markers";
}

TEST(ParameterTable, EveryRowIsReadAndWrittenByTheConfig) {
  // each row with an accessor round-trips through the canonical JSON; rows are unique
  std::set<std::string> paths;
  for (const ParamSpec& p : job_parameters()) {
    EXPECT_TRUE(paths.insert(std::string(p.path)).second) << p.path << " twice";
    EXPECT_FALSE(p.doc.empty()) << p.path;
    EXPECT_FALSE(p.unit.empty()) << p.path;
    if (p.omit_at_default) {
      EXPECT_FALSE(p.sql_column.empty()) << p.path << ": a new parameter needs its SQL column";
    }
  }
  for (const char* model : {"sp", "dp_smooth"}) {
    SimConfig c = SimConfig::from_json({{"model", model}, {"w", 4}, {"zeta", 0.1}, {"mu", 1}, {"mu_n", 0.5},
                                        {"drag_rate", 0.2}});
    const json j = c.to_json();
    for (const ParamSpec& p : job_parameters()) {
      if (p.path == "theta_w_deg" || p.path == "seed" || (p.models == ParamModels::DpSmooth) ||
          (p.models == ParamModels::Sp && std::string(model) != "sp") ||
          (p.models == ParamModels::Dp && std::string(model) == "sp") ||
          (p.omit_at_default && p.path != "mu_n" && p.path != "drag_rate"))  // at their defaults: omitted
        continue;
      const std::string path(p.path);
      const auto dot = path.find('.');
      const bool has = dot == std::string::npos ? j.contains(path) : j.contains(path.substr(0, dot)) &&
                                                                         j[path.substr(0, dot)].contains(path.substr(dot + 1));
      EXPECT_TRUE(has) << model << ": " << path << " missing from the canonical job";
    }
    EXPECT_EQ(SimConfig::from_json(j).to_json(), j);
  }
}

TEST(ParameterTable, NewParametersAppearAsTypedSqlColumnsWithTheirDefaults) {
  const std::string path = (fs::temp_directory_path() / ("beverloo-params-" + new_token() + ".sqlite")).string();
  {
    db::Database db{path, db::Database::Mode::ReadWrite};
    db::open_store(db);
    CampaignStore store{db};
    const json sweep = {{"base", {{"N", 50}, {"W", 12}, {"w", 4}, {"zeta", 0.0}, {"mu", 8.5}}},
                        {"sweep", {{"union", json::array({json{{"mu_n", json::array({0.0})}, {"drag_rate", json::array({1.96})}},
                                                          json{{"E_sp", json::array({140})}}})}}}};
    const Sweep s = Sweep::parse(sweep, "t");
    store.create_campaign(s, sweep.dump(), s.expand());
    db::Statement st = db.prepare("SELECT mu_n, mu_t, drag_rate, lambda, contact_width IS NULL FROM runs ORDER BY E_sp");
    ASSERT_TRUE(st.step());  // the authors' friction split and drag (E_sp = 100)
    EXPECT_EQ(st.get_double(0), 0.0);
    EXPECT_EQ(st.get_double(1), 8.5) << "mu_t defaults to mu";
    EXPECT_EQ(st.get_double(2), 1.96);
    EXPECT_NEAR(st.get_double(3), 1.96 * units::pi / 4 / 8.5, 1e-12) << "lambda = drag_rate M(sigma_avg) / mu_t";
    EXPECT_EQ(st.get_int(4), 1) << "contact_width is NULL for SP";
    ASSERT_TRUE(st.step());  // the text's model: the split is mu, no rate drag
    EXPECT_EQ(st.get_double(0), 8.5);
    EXPECT_EQ(st.get_double(2), 0.0);
    EXPECT_EQ(st.get_double(3), 0.0);
  }
  {  // opening again adds nothing and keeps the view
    db::Database db{path, db::Database::Mode::ReadWrite};
    db::open_store(db);
    EXPECT_EQ(db.scalar_int("SELECT count(*) FROM runs"), 2);
  }
  for (const char* ext : {"", "-wal", "-shm"}) fs::remove(path + ext);
}

}  // namespace
}  // namespace beverloo
