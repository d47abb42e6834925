// Draining-hopper data files (orchestrator/experiment): the reader names the line and column of
// every problem, the counts form gives the same exits as the exits form, the units follow the
// paper (g_eff from the densities, t0 = sqrt(sigma/g_eff)), an import stores its series with
// each run's Q = c0 t0, refuses a second series of the same name unless told to replace it,
// and the campaign fits see it as a series of its own, labelled measured or simulated.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"
#include "orchestrator/experiment/experiment_store.h"
#include "reports/campaign_fits.h"

namespace beverloo {
namespace {
namespace fs = std::filesystem;
using namespace experiment;

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("beverloo-exp-" + new_token());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
};

/// Exits of the law N(t) = (sqrt(N0) - c0 t / 2)^2 (seconds) for a run named `run`.
std::string law_rows(const std::string& run, double w_m, int n0, double c0_per_s) {
  std::ostringstream o;
  o.precision(17);
  for (int k = 0; k < n0; ++k)
    o << run << "," << w_m << "," << 2 * (std::sqrt(double(n0)) - std::sqrt(double(n0 - k - 1))) / c0_per_s << "\n";
  return o.str();
}

const char* kHeader =
    "# beverloo-exits 1\n# series: test drains\n# provenance: measured\n# source: the test's own law\n"
    "# geometry: 45/45\n# sigma_avg_m: 3e-4\n# rho_drop_kg_m3: 936\n# rho_medium_kg_m3: 997\n";

std::string error_of(const std::string& path) {
  try {
    (void)prepare_import(path, ImportOptions{});
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ExperimentFile, ImportFitsEachRunAndConvertsToTheUnitsOfThePaper) {
  TempDir d;
  const std::string path = d.write("a.csv", std::string(kHeader) + "run,w_m,t_s\n" + law_rows("r1", 9e-4, 500, 20) +
                                                law_rows("r2", 1.5e-3, 500, 30));
  const PreparedImport p = prepare_import(path, ImportOptions{});
  // g_eff = g (rho_w - rho_o) / rho_o = 9.80665 * 61 / 936, t0 = sqrt(3e-4 / g_eff)
  const double g_eff = 9.80665 * 61 / 936;
  EXPECT_NEAR(p.units.g_eff_m_s2, g_eff, 1e-12);
  EXPECT_NEAR(p.units.t0_s, std::sqrt(3e-4 / g_eff), 1e-15);
  ASSERT_EQ(p.runs.size(), 2u);
  EXPECT_EQ(p.series, "test drains");
  EXPECT_EQ(p.provenance, "measured");
  EXPECT_NEAR(p.runs[0].w, 3.0, 1e-12);
  EXPECT_NEAR(p.runs[1].w, 5.0, 1e-12);
  ASSERT_TRUE(p.runs[0].fit.ok) << p.runs[0].fit.message;
  EXPECT_NEAR(p.runs[0].fit.c0, 20, 20 * 3e-3);
  EXPECT_NEAR(p.runs[1].Q, 30 * p.units.t0_s, 30 * p.units.t0_s * 3e-3);

  TempDir db_dir;
  db::Database db((db_dir.path / "campaign.sqlite").string(), db::Database::Mode::ReadWrite);
  db::open_store(db);
  store_import(db, p, false);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_results WHERE series = 'test drains'"), 2);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_exits"), 1000);
  // a second import of the same name is refused, and changes nothing; --replace replaces
  EXPECT_THROW(store_import(db, p, false), ConfigError);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_runs"), 2);
  store_import(db, p, true);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_runs"), 2);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_exits"), 1000);
  // the fits see it: one series, labelled measured, with its two widths (too few to fit)
  CampaignFits fits = fit_campaign(db);
  ASSERT_EQ(fits.series.size(), 1u);
  EXPECT_EQ(fits.series[0].provenance, "measured");
  EXPECT_NE(fits.series[0].label.find("(measured"), std::string::npos) << fits.series[0].label;
  EXPECT_EQ(fits.series[0].points.size(), 2u);
  EXPECT_FALSE(fits.series[0].fit.has_value());
  store_fits(db, fits);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM experiment_fit_results"), 1);
}

TEST(ExperimentFile, TheCommandLinesGravityOverridesTheHeaders) {
  // docs/experiments.md: the command line overrides the header, the effective gravity as a
  // whole (the header here gives the two densities)
  TempDir d;
  const std::string path = d.write("a.csv", std::string(kHeader) + "run,w_m,t_s\n" + law_rows("r1", 9e-4, 500, 20));
  ImportOptions o;
  o.units.g_eff_m_s2 = 0.5;
  EXPECT_NEAR(prepare_import(path, o).units.g_eff_m_s2, 0.5, 1e-15);
  o.units = {};
  o.units.rho_drop_kg_m3 = 900;  // one density on the line, the other from the header
  EXPECT_NEAR(prepare_import(path, o).units.g_eff_m_s2, 9.80665 * 97 / 900, 1e-12);
  // both ways on the line is a contradiction, named by the option
  o.units.g_eff_m_s2 = 0.5;
  try {
    (void)prepare_import(path, o);
    FAIL() << "--g-eff with --rho-drop was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "--g-eff");
  }
  // and in the file alone, too
  const std::string both = d.write("b.csv", std::string(kHeader) + "# g_eff_m_s2: 0.5\nrun,w_m,t_s\n" + law_rows("r1", 9e-4, 500, 20));
  EXPECT_NE(error_of(both).find("not both"), std::string::npos) << error_of(both);
}

TEST(ExperimentFile, CountsGiveTheSameExitsAsExitTimes) {
  TempDir d;
  // N after each time: 5 at 0, then 4, 4 (no change), 2 (two at once), 0
  const std::string counts = d.write("c.csv", std::string(kHeader) + "run,w_m,t_s,N\nr,1e-3,0,5\nr,1e-3,1,4\n"
                                                                       "r,1e-3,2,4\nr,1e-3,3,2\nr,1e-3,4.5,0\n");
  const ExperimentFile f = read_csv(counts);
  ASSERT_EQ(f.runs.size(), 1u);
  EXPECT_EQ(f.runs[0].n_initial, 5);
  EXPECT_EQ(f.runs[0].exit_t_s, (std::vector<double>{1, 3, 3, 4.5, 4.5}));
  const std::string exits = d.write("e.csv", std::string(kHeader) + "run,w_m,t_s\nr,1e-3,2\nr,1e-3,3\nr,1e-3,5\n");
  const ExperimentFile g = read_csv(exits);
  EXPECT_EQ(g.runs[0].n_initial, 3);
  EXPECT_EQ(g.runs[0].exit_t_s, (std::vector<double>{0, 1, 3}));  // from the run's first time
}

TEST(ExperimentFile, EveryProblemNamesTheFileLineAndColumn) {
  TempDir d;
  struct Case {
    std::string body, expect;
  };
  const std::string h = kHeader;
  const std::vector<Case> cases = {
      {h + "run,w_m,t_s\nr,1e-3,0\nr,1e-3,x\n", "c.csv:11 column t_s"},
      {h + "run,w_m,t_s\nr,-1,0\n", "c.csv:10 column w_m"},
      {h + "run,w_m,t_s\nr,1e-3,5\nr,1e-3,4\n", "goes back"},
      {h + "run,w_m,t_s\nr,1e-3,0\nr,2e-3,1\n", "changes its orifice width"},
      {h + "run,w_m,t_s\na,1e-3,0\nb,1e-3,0\na,1e-3,1\n", "rows must be together"},
      {h + "run,w_m,t_s,N\nr,1e-3,0,5\nr,1e-3,1,6\n", "only falls"},
      {h + "run,w_m,t_s,N\nr,1e-3,0,2.5\n", "column N"},
      {h + "run,w_m\nr,1e-3\n", "must include run, w_m and t_s"},
      {h + "run,w_m,t_s,depth\n", "unknown column \"depth\""},
      {h + "run,w_m,t_s\nr,1e-3\n", "has 2 cells"},
      {h + "run,w_m,t_s\n", "no data rows"},
      {h + "# colour: red\nrun,w_m,t_s\nr,1e-3,0\n", "unknown header key \"colour\""},
      {h + "# series: twice\nrun,w_m,t_s\nr,1e-3,0\n", "given twice"},
      {"# sigma_avg_m: 3e-4\n# g_eff_m_s2: 0.6\nrun,w_m,t_s\nr,1e-3,0\n", "provenance"},
      {"# provenance: measured\n# g_eff_m_s2: 0.6\nrun,w_m,t_s\nr,1e-3,0\n", "sigma_avg_m"},
      {"# provenance: measured\n# sigma_avg_m: 3e-4\nrun,w_m,t_s\nr,1e-3,0\n", "effective gravity"},
      {"# provenance: guessed\n# sigma_avg_m: 3e-4\n# g_eff_m_s2: 1\nrun,w_m,t_s\nr,1e-3,0\n", "\"measured\" or \"simulated\""},
      {"# provenance: measured\n# sigma_avg_m: 0\n# g_eff_m_s2: 1\nrun,w_m,t_s\nr,1e-3,0\n", "sigma_avg_m"},
      {"# provenance: measured\n# sigma_avg_m: 3e-4\n# g_eff_m_s2: 1\n# rho_drop_kg_m3: 900\nrun,w_m,t_s\nr,1e-3,0\n",
       "not both"},
      {std::string("run,w_m,t_s\nr,1e-3,0\0\n", 23), "NUL"},
  };
  for (const Case& k : cases) {
    const std::string path = d.write("c.csv", k.body);
    const std::string e = error_of(path);
    EXPECT_NE(e.find(k.expect), std::string::npos) << "expected \"" << k.expect << "\" in: " << e;
    EXPECT_NE(e.find("c.csv"), std::string::npos) << e;
  }
  EXPECT_NE(error_of((d.path / "missing.csv").string()).find("no such file"), std::string::npos);
  EXPECT_NE(error_of(d.path.string()).find("not a regular file"), std::string::npos);
}

}  // namespace
}  // namespace beverloo
