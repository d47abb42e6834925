// `campaign explain`: a cached job is found by its key or its file; an uncached one is shown
// beside the nearest finished job with exactly the identity fields in which they differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "orchestrator/campaign/job_explain.h"
#include "orchestrator/campaign/store.h"
#include "orchestrator/db/migrations.h"
#include "orchestrator/sweep/sweep.h"

namespace beverloo {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

std::vector<std::string> identity_free(const SimConfig& c) { return identity_free_paths(c); }

TEST(JobExplain, CachedJobsAreFoundAndOthersShowTheirNearestFinishedJob) {
  const std::string path = (fs::temp_directory_path() / ("beverloo-explain-" + new_token() + ".sqlite")).string();
  {
    db::Database db(path, db::Database::Mode::ReadWrite);
    db::open_store(db);
    CampaignStore store(db);
    const json sweep = {{"base", {{"N", 50}, {"W", 12}, {"zeta", 0.3}, {"mu", 0.0}}}, {"sweep", {{"w", {4, 5, 7}}}}};
    const Sweep s = Sweep::parse(sweep, "test");
    const std::vector<JobSpec> jobs = s.expand();
    store.create_campaign(s, sweep.dump(), jobs);
    db.exec("UPDATE jobs SET state = 'done' WHERE key = '" + jobs[0].key + "' OR key = '" + jobs[2].key + "'");

    // a finished job: cached, by its key or by its file, also with a setting that cannot change its result
    JobExplanation x = explain_job(db, jobs[0].key, jobs[0].job, identity_free(jobs[0].config));
    ASSERT_TRUE(x.found);
    EXPECT_EQ(x.found->state, "done");
    EXPECT_FALSE(x.nearest);
    SimConfig other_skin = jobs[0].config;
    other_skin.skin = 0.55;
    EXPECT_EQ(job_key(other_skin), jobs[0].key);
    EXPECT_EQ(find_stored_job(db, jobs[0].key.substr(0, 10)).first, jobs[0].key);
    EXPECT_THROW(find_stored_job(db, "abc"), std::invalid_argument);
    EXPECT_THROW(find_stored_job(db, "not-hex!"), std::invalid_argument);

    // a pending job: in the store, not cached; its nearest finished job differs in w alone
    x = explain_job(db, jobs[1].key, jobs[1].job, identity_free(jobs[1].config));
    ASSERT_TRUE(x.found);
    EXPECT_EQ(x.found->state, "pending");
    ASSERT_TRUE(x.nearest);
    ASSERT_EQ(x.differences.size(), 1u);
    EXPECT_EQ(x.differences[0].field, "w");
    EXPECT_EQ(x.differences[0].asked, "5.0");
    // of the two finished jobs that differ in w alone (4 and 7), the nearer number: 4
    EXPECT_EQ(x.nearest->key, jobs[0].key);
    EXPECT_EQ(x.differences[0].stored, "4.0");
    SimConfig w65 = jobs[0].config;
    w65.w = 6.5;
    w65.resolve_and_validate();
    x = explain_job(db, job_key(w65), w65.to_json(), identity_free(w65));
    ASSERT_TRUE(x.nearest);
    EXPECT_EQ(x.nearest->key, jobs[2].key) << "w = 6.5 is nearer 7 than 4";

    // a new job differing in two identity fields and one free field (the skin)
    SimConfig c = jobs[0].config;
    c.w = 4.5;
    c.zeta = 0.31;
    c.skin = 0.6;
    c.resolve_and_validate();
    x = explain_job(db, job_key(c), c.to_json(), identity_free(c));
    EXPECT_FALSE(x.found);
    ASSERT_TRUE(x.nearest);
    std::set<std::string> fields;
    for (const FieldDifference& d : x.differences) fields.insert(d.field);
    EXPECT_EQ(fields, (std::set<std::string>{"w", "zeta"})) << "the skin is not part of a job's identity";
    const std::vector<std::string> free = identity_free(c);
    EXPECT_NE(std::find(free.begin(), free.end(), "skin"), free.end());
    EXPECT_EQ(std::find(free.begin(), free.end(), "w"), free.end());

    // the same fields under another key: only the engine version can differ
    x = explain_job(db, std::string(64, 'f'), jobs[2].job, identity_free(jobs[2].config));
    EXPECT_FALSE(x.found);
    ASSERT_TRUE(x.nearest);
    EXPECT_EQ(x.nearest->key, jobs[2].key);
    EXPECT_TRUE(x.only_engine_differs);
  }
  for (const char* ext : {"", "-wal", "-shm"}) fs::remove(path + ext);
}

}  // namespace
}  // namespace beverloo
