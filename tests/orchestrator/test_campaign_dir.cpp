// The campaign directory: one layout, lock before open before migrate, the same answer for a
// missing campaign from every opener, and nothing created by a command that only needed one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "orchestrator/campaign/campaign_dir.h"
#include "orchestrator/campaign/store.h"

namespace beverloo {
namespace {
namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("beverloo-dir-" + new_token());
  ~TempDir() { fs::remove_all(path); }
};

TEST(CampaignDir, OpeningAMissingCampaignSaysSoAndCreatesNothing) {
  TempDir t;
  const std::string dir = (t.path / "absent").string();
  EXPECT_THROW(CampaignWriter(dir, CampaignWriter::Open::MustExist), MissingCampaign);
  EXPECT_THROW(CampaignReader{dir}, MissingCampaign);
  EXPECT_FALSE(fs::exists(dir)) << "neither opener may leave a directory behind";
  try {
    CampaignReader r(dir);
  } catch (const MissingCampaign& e) {
    EXPECT_NE(std::string(e.what()).find(dir), std::string::npos) << "the message names the directory";
  }
}

TEST(CampaignDir, SomethingElseNamedCampaignSqliteIsNoCampaign) {
  TempDir t;
  fs::create_directories(t.path / campaign_dir::kDatabaseFile);  // a directory, not a store
  EXPECT_FALSE(campaign_dir::holds_campaign(t.path.string()));
  EXPECT_THROW(CampaignReader{t.path.string()}, MissingCampaign);
}

TEST(CampaignDir, CreatingLaysOutTheDirectoryAndOneWriterHoldsIt) {
  TempDir t;
  const std::string dir = t.path.string();
  {
    CampaignWriter w(dir, CampaignWriter::Open::CreateIfMissing);
    EXPECT_TRUE(fs::is_directory(t.path / campaign_dir::kJobsDir));
    EXPECT_TRUE(campaign_dir::holds_campaign(dir));
    EXPECT_GE(w.db().scalar_int("PRAGMA user_version"), 1) << "migrated on open";
    EXPECT_THROW(CampaignWriter(dir, CampaignWriter::Open::MustExist), CampaignBusy) << "a second writer";
    CampaignReader r(dir);  // readers do not take the lock
    EXPECT_EQ(r.db().scalar_int("PRAGMA user_version"), w.db().scalar_int("PRAGMA user_version"));
  }
  CampaignWriter again(dir, CampaignWriter::Open::MustExist);  // the lock went with its holder
  std::ifstream lock(t.path / campaign_dir::kLockFile);
  std::string holder;
  std::getline(lock, holder);
  EXPECT_NE(holder.find("pid"), std::string::npos) << "the lock says who holds it";
}

TEST(CampaignDir, JobDirectoriesAreNamedByTheirKeysFirstSixteenCharacters) {
  EXPECT_EQ(campaign_dir::job_dir_relative("0123456789abcdef0123"), "jobs/0123456789abcdef");
}

}  // namespace
}  // namespace beverloo
