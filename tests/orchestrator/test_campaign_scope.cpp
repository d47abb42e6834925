// Which campaigns of a directory `fit` and `report` read (orchestrator/campaign/campaign_scope.h):
// the latest by default, one by id, or all of them with each shared job once.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "orchestrator/campaign/campaign_scope.h"
#include "orchestrator/campaign/job_speed.h"
#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"
#include "reports/campaign_fits.h"
#include "reports/fit.h"
#include "reports/report.h"

namespace beverloo {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

/// A campaign directory holding two campaigns run one after the other: the first a drag-only
/// series at w = 4..8 (replica 0), the second the same widths with replicas 0 and 1 and a
/// friction-only series: its replica 0 drag jobs are the first campaign's jobs (the same keys).
/// Every run follows Q = 0.4 (w - 1)^beta exactly (1 % errors), beta 1/2 with drag, 3/2 with friction.
fs::path two_campaigns() {
  const fs::path dir = fs::temp_directory_path() / ("beverloo-scope-" + new_token());
  fs::create_directories(dir / "jobs");
  db::Database db((dir / "campaign.sqlite").string(), db::Database::Mode::ReadWrite);
  db::open_store(db);
  CampaignStore store(db);
  const json first = {{"name", "first"}, {"base", {{"N", 400}, {"W", 25}}},
                      {"sweep", {{"product", {{{"lambda", {"inf"}}}, {{"w", {4, 5, 6, 7, 8}}}}}}}};
  const json second = {{"name", "second"}, {"base", {{"N", 400}, {"W", 25}}}, {"replicas", 2},
                       {"sweep", {{"product", {{{"lambda", {"inf", 0}}}, {{"w", {4, 5, 6, 7, 8}}}}}}}};
  for (const json& sweep : {first, second}) {
    const Sweep s = Sweep::parse(sweep, sweep["name"].get<std::string>());
    const std::int64_t id = store.create_campaign(s, sweep.dump(), s.expand());
    while (auto job = store.claim_next(id, "local", "test")) {
      const json j = json::parse(job->job_json);
      const double beta = j["mu"].get<double>() > 0 ? 1.5 : 0.5;
      const double Q = beverloo_model(j["w"].get<double>(), 0.4, 1.0, beta);
      const json summary = {{"status", "converged"}, {"Q", Q}, {"Q_err", 0.01 * Q}, {"Q_rel_err", 0.01},
                            {"window_start", 20}, {"window_end", 200}, {"exits_in_window", 500},
                            {"exits_total", 600}, {"clogged", false}, {"clog_time", -1}, {"rho_n", 1.1},
                            {"a_eff", 0.9}, {"Q_prime", Q}, {"Q_prime_err", 0.02 * Q}, {"mean_F_drag", 0.1},
                            {"mean_F_friction", 0.2}, {"force_ratio", 0.5}, {"dt", 1e-3}, {"steps", 1000},
                            {"wall_seconds", 2.0}, {"t_end", 200}, {"particle_steps_per_second", 3e7}};
      store.ingest_success(*job, summary.dump(), {}, {}, {});
    }
  }
  return dir;
}

/// Points per series label part ("mu=0" for drag only), counting replicas.
int points_of(const CampaignFits& fits, bool drag_only) {
  int n = 0;
  for (const Series& s : fits.series)
    if ((s.mu == 0) == drag_only) n += static_cast<int>(s.job_keys.size());
  return n;
}

TEST(CampaignScope, LatestIsTheDefaultOneReadsItsIdAndAllReadsEverySharedJobOnce) {
  const fs::path dir = two_campaigns();
  db::Database db((dir / "campaign.sqlite").string(), db::Database::Mode::ReadOnly);
  // 5 drag jobs in the first campaign; the second has 10 drag (5 of them the first's) and 10 friction
  const CampaignFits latest = fit_campaign(db);
  EXPECT_EQ(points_of(latest, true), 10);
  EXPECT_EQ(points_of(latest, false), 10);
  const CampaignFits first = fit_campaign(db, FlowRate::Q, CampaignScope::one(1));
  EXPECT_EQ(points_of(first, true), 5);
  EXPECT_EQ(points_of(first, false), 0);
  const CampaignFits all = fit_campaign(db, FlowRate::Q, CampaignScope::all());
  EXPECT_EQ(points_of(all, true), 10) << "a job in two campaigns is one point, not two";
  EXPECT_EQ(points_of(all, false), 10);
  // every job key in scope once
  for (const Series& s : all.series) {
    std::vector<std::string> keys = s.job_keys;
    std::sort(keys.begin(), keys.end());
    EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end()) << s.label;
  }
  // the jobs' speed counts each job once too
  const std::vector<ModelSpeed> speed = campaign_speed(db, CampaignScope::all());
  ASSERT_EQ(speed.size(), 1u);
  EXPECT_EQ(speed[0].jobs, 20);
  EXPECT_EQ(campaign_speed(db, CampaignScope::one(1))[0].jobs, 5);
  fs::remove_all(dir);
}

TEST(CampaignScope, AllPutsTheFirstCampaignsJobsFirst) {
  const fs::path dir = two_campaigns();
  db::Database db((dir / "campaign.sqlite").string(), db::Database::Mode::ReadOnly);
  const CampaignFits all = fit_campaign(db, FlowRate::Q, CampaignScope::all());
  ASSERT_FALSE(all.series.empty());
  EXPECT_EQ(all.series[0].mu, 0) << "the first campaign's drag-only series is read first";
  const CampaignFits first = fit_campaign(db, FlowRate::Q, CampaignScope::one(1));
  ASSERT_EQ(first.series.size(), 1u);
  // its first five keys are the first campaign's, in that campaign's order
  ASSERT_GE(all.series[0].job_keys.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(all.series[0].job_keys[i], first.series[0].job_keys[i]);
  fs::remove_all(dir);
}

TEST(CampaignScope, ParseAcceptsLatestAllAndAPositiveIdOnly) {
  EXPECT_FALSE(CampaignScope::parse("latest", "--campaign").is_all());
  EXPECT_TRUE(CampaignScope::parse("all", "--campaign").is_all());
  EXPECT_NO_THROW(CampaignScope::parse("12", "--campaign"));
  for (const char* bad : {"", "0", "-1", "+3", " 3", "3abc", "ALL", "1e3", "99999999999999999999", "1; DROP TABLE jobs"}) {
    try {
      CampaignScope::parse(bad, "--campaign");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("--campaign"), std::string::npos) << e.what();
    }
  }
}

TEST(CampaignScope, AnIdThatIsNotThereIsRefusedBeforeTheReportWritesAnything) {
  const fs::path dir = two_campaigns();
  {
    db::Database db((dir / "campaign.sqlite").string(), db::Database::Mode::ReadOnly);
    EXPECT_NO_THROW(CampaignScope::one(2).check_exists(db, "--campaign"));
    try {
      CampaignScope::one(3).check_exists(db, "--campaign");
      ADD_FAILURE() << "campaign 3 accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("1, 2"), std::string::npos) << "names the campaigns there: " << e.what();
    }
  }
  const fs::path out = dir / "report";
  EXPECT_THROW(write_report(dir.string(), out.string(), CampaignScope::one(3)), ConfigError);
  EXPECT_FALSE(fs::exists(out)) << "nothing written";
  db::Database db((dir / "campaign.sqlite").string(), db::Database::Mode::ReadOnly);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM beverloo_fit_results"), 0) << "no fits stored";
  fs::remove_all(dir);
}

TEST(CampaignScope, TheReportOfAllCampaignsCoversBothAndSaysSo) {
  const fs::path dir = two_campaigns();
  const fs::path out = dir / "report";
  write_report(dir.string(), out.string(), CampaignScope::all());
  std::ifstream in(out / "index.html");
  std::stringstream html;
  html << in.rdbuf();
  EXPECT_NE(html.str().find("every campaign (2)"), std::string::npos);
  EXPECT_NE(html.str().find("beverloo report: second"), std::string::npos) << "the heading names the latest";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace beverloo
