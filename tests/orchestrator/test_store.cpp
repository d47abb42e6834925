// The campaign store: migrations, sharing jobs between campaigns, claiming, idempotent
// ingestion, the retry policy, and refusing foreign or newer databases.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"

namespace beverloo {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

struct TempDb {
  std::string path;
  TempDb() {
    path = (fs::temp_directory_path() / ("beverloo-store-" + new_token() + ".sqlite")).string();
  }
  ~TempDb() {
    for (const char* ext : {"", "-wal", "-shm"}) fs::remove(path + ext);
  }
};

Sweep sweep_of(const json& j) { return Sweep::parse(j, "test"); }

/// A fresh, migrated store in a temporary file.
class StoreTest : public ::testing::Test {
 protected:
  TempDb t;
  db::Database db{t.path, db::Database::Mode::ReadWrite};
  CampaignStore store{db};
  void SetUp() override { db::open_store(db); }
  std::int64_t create(const json& sweep) {
    const Sweep s = sweep_of(sweep);
    return store.create_campaign(s, sweep.dump(), s.expand());
  }
};
json small(const json& sweep) { return {{"base", {{"N", 50}, {"W", 12}, {"zeta", 0.3}, {"mu", 0.0}}}, {"sweep", sweep}}; }

TEST(Store, MigratesAnEmptyFileAndChecksIdentity) {
  TempDb t;
  {
    db::Database db(t.path, db::Database::Mode::ReadWrite);
    db::open_store(db);
    EXPECT_EQ(db.scalar_int("PRAGMA user_version"), db::known_schema_version());
    EXPECT_EQ(db.scalar_int("PRAGMA application_id"), db::kApplicationId);
    EXPECT_EQ(db.scalar_int("SELECT count(*) FROM sqlite_schema WHERE name IN ('campaigns', 'jobs', 'attempts', 'results', 'velocity_profiles', 'runs')"), 6);
    db::open_store(db);  // reopening migrates nothing and changes nothing
    EXPECT_EQ(db.scalar_int("PRAGMA user_version"), db::known_schema_version());
  }
  {
    db::Database db(t.path, db::Database::Mode::ReadWrite);
    db.exec("PRAGMA user_version = 999");
    EXPECT_THROW(db::open_store(db), db::DbError) << "a newer schema must be refused";
  }
}

TEST(Store, RefusesAnotherApplicationsDatabase) {
  TempDb t;
  {
    db::Database db(t.path, db::Database::Mode::ReadWrite);
    db.exec("CREATE TABLE foreign_data (x)");
  }
  db::Database db(t.path, db::Database::Mode::ReadWrite);
  EXPECT_THROW(db::open_store(db), db::DbError);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM sqlite_schema"), 1) << "nothing may be added to a foreign file";
}

TEST_F(StoreTest, CampaignsShareJobsAndRecreatingChangesNothing) {
  const json a = small({{"w", {3, 4, 5}}});
  const json b = small({{"w", {5, 6}}});
  const Sweep sa = sweep_of(a), sb = sweep_of(b);
  const std::int64_t ida = store.create_campaign(sa, a.dump(), sa.expand());
  EXPECT_EQ(store.create_campaign(sa, a.dump(), sa.expand()), ida);
  const std::int64_t idb = store.create_campaign(sb, b.dump(), sb.expand());
  EXPECT_NE(ida, idb);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM jobs"), 4) << "w = 5 is one job shared by both campaigns";
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM campaign_jobs"), 5);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM jobs WHERE w > 4 AND lambda > 1e300"), 2) << "typed columns; lambda = inf";
}

TEST_F(StoreTest, ClaimIngestIsIdempotentAndSharedResultsAreNotRerun) {
  const std::int64_t id = create(small({{"w", {3, 4}}}));
  auto job = store.claim_next(id, "local", "host");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->attempt_no, 1);
  EXPECT_EQ(store.counts(id).running, 1);
  const std::string summary = json{{"status", "converged"}, {"Q", 1.5}, {"Q_err", 0.1}, {"Q_rel_err", 0.066},
                                   {"window_start", 20}, {"window_end", 200}, {"exits_in_window", 100},
                                   {"exits_total", 120}, {"clogged", false}, {"clog_time", -1}, {"rho_n", 1.1},
                                   {"a_eff", 0.9}, {"Q_prime", 1.4}, {"Q_prime_err", 0.1}, {"mean_F_drag", 0.3},
                                   {"mean_F_friction", 0}, {"force_ratio", nullptr}, {"dt", 1e-3}, {"steps", 200000},
                                   {"wall_seconds", 3.0}, {"particle_steps_per_second", 3e7}, {"t_end", 210.0}}
                                  .dump();
  store.ingest_success(*job, summary, {0, 0.5}, {1, 2}, {0.1, 0.1});
  store.ingest_success(*job, summary, {0, 0.5}, {1, 2}, {0.1, 0.1});  // a second ingestion changes nothing
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM results"), 1);
  // the job's speed in the runs view: 210 t0 in 3 s of engine time = 4200 t0 per CPU-minute
  db::Statement speed = db.prepare("SELECT t0_per_cpu_minute FROM runs WHERE status IS NOT NULL");
  ASSERT_TRUE(speed.step());
  EXPECT_DOUBLE_EQ(speed.get_double(0), 4200.0);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM velocity_profiles"), 2);
  EXPECT_EQ(store.counts(id).done, 1);
  // another campaign containing the finished job does not run it again
  const std::int64_t id2 = create(small({{"w", {3}}}));
  EXPECT_FALSE(store.claim_next(id2, "local", "host")) << "the job already has a result";
  EXPECT_EQ(store.counts(id2).done, 1);
}

TEST_F(StoreTest, RetryPolicyChargesScienceFailuresOnly) {
  const std::int64_t id = create(small({{"w", {3, 4}}}));
  const int max_retries = 1;
  // infrastructure failures: back to pending, budget untouched, however often
  for (int k = 0; k < 5; ++k) {
    auto j = store.claim_next(id, "local", "h");
    ASSERT_TRUE(j);
    EXPECT_EQ(store.record_failure(j->attempt_id, j->key, FailureClass::Killed, 137, "killed", max_retries), "pending");
  }
  EXPECT_EQ(db.scalar_int("SELECT max(retries_used) FROM jobs"), 0);
  // i/o failures and crashes: one retry, then failed
  auto j = store.claim_next(id, "local", "h");
  EXPECT_EQ(store.record_failure(j->attempt_id, j->key, FailureClass::Io, 4, "write", max_retries), "pending");
  j = store.claim_next(id, "local", "h");
  EXPECT_EQ(store.record_failure(j->attempt_id, j->key, FailureClass::Internal, 1, "bug", max_retries), "failed");
  // invalid parameters and blow-ups (a retry would blow up at the same step): failed at once
  j = store.claim_next(id, "local", "h");
  EXPECT_EQ(store.record_failure(j->attempt_id, j->key, FailureClass::BlowUp, 3, "NaN", max_retries), "failed");
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM jobs WHERE state = 'failed' AND retries_used = 0"), 1);
  EXPECT_EQ(store.counts(id).failed, 2);
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM attempts WHERE failure_class = 'killed'"), 5);
  EXPECT_EQ(store.retry(id, false), 2);
  EXPECT_EQ(store.counts(id).pending, 2);
  EXPECT_EQ(store.cancel(id), 2);
  EXPECT_EQ(store.counts(id).cancelled, 2);
}

TEST_F(StoreTest, InsertingTenThousandJobsIsFast) {
  const json j = {{"base", {{"N", 50}, {"W", 12}}},
                  {"sweep", {{"product", {{{"w", {{"linspace", {2, 10, 100}}}}}, {{"lambda", {{"logspace", {-3, 2, 100}}}}}}}}}};
  const auto t0 = std::chrono::steady_clock::now();
  const Sweep s = sweep_of(j);
  const auto jobs = s.expand();
  const auto t1 = std::chrono::steady_clock::now();
  store.create_campaign(s, j.dump(), jobs);
  const auto t2 = std::chrono::steady_clock::now();
  EXPECT_EQ(db.scalar_int("SELECT count(*) FROM jobs"), 10000);
  std::printf("10000 jobs: expand %.3f s, insert %.3f s\n", std::chrono::duration<double>(t1 - t0).count(),
              std::chrono::duration<double>(t2 - t1).count());
}

}  // namespace
}  // namespace beverloo
