#pragma once
/// \file campaign_dir.h
/// \brief The one place that knows a campaign directory's layout and how it is opened:
///
///     DIR/campaign.sqlite     the store (schema/*.sql, docs/database.md)
///     DIR/coordinator.lock    flock of the one process that writes the store
///     DIR/jobs/<key16>/       one directory per job (job_files.h, the engine's files)
///     DIR/report/             fits, tables and figures (reports/)
///
/// Writers (`run`, `campaign create|cancel|retry`, `fit`, `report`) take the lock, then open
/// and migrate the store: CampaignWriter. Readers (`query`, `campaign status|list`) open it
/// read-only and change nothing, not even in a read-only directory: CampaignReader. Both say
/// the same thing, with the same exit code, when DIR holds no campaign.
#include <stdexcept>
#include <string>

#include "orchestrator/db/database.h"

namespace beverloo {

namespace campaign_dir {
inline constexpr const char* kDatabaseFile = "campaign.sqlite";
inline constexpr const char* kLockFile = "coordinator.lock";
inline constexpr const char* kJobsDir = "jobs";
inline constexpr const char* kReportDir = "report";

std::string database_path(const std::string& dir);
std::string report_path(const std::string& dir);
/// A job's directory relative to the campaign directory (stored in jobs.dir).
std::string job_dir_relative(const std::string& job_key);
/// True if DIR holds a store file (a regular file named campaign.sqlite).
bool holds_campaign(const std::string& dir);
/// Reads the store file's 100-byte SQLite header, with plain file reads (no SQLite, no lock, no
/// WAL files), and throws ConfigError naming the file if it is not ours: not a regular file, not
/// an SQLite database, another application's (application_id), or a newer schema (user_version).
/// Absent or empty: fine (a new campaign). Every opener calls it before anything else, so that
/// a refusal leaves the directory exactly as it was.
void check_store_file(const std::string& dir);
}  // namespace campaign_dir

/// DIR holds no campaign.sqlite (or something else by that name): bad input, exit code 2.
class MissingCampaign : public std::runtime_error {
 public:
  explicit MissingCampaign(const std::string& dir);
};

/// Another coordinator (or writer) holds the campaign: exit code 6.
class CampaignBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The campaign lock: one writer per campaign directory (flock on coordinator.lock; the
/// holder's host, pid and start time are written into it). Throws CampaignBusy if another
/// one lives. A dead holder's lock dies with its process.
class CoordinatorLock {
 public:
  explicit CoordinatorLock(const std::string& dir);
  ~CoordinatorLock();
  CoordinatorLock(const CoordinatorLock&) = delete;
  CoordinatorLock& operator=(const CoordinatorLock&) = delete;

 private:
  int fd_ = -1;
};

/// Lock, open read-write, migrate: in that order, so that no two processes migrate at once.
class CampaignWriter {
 public:
  enum class Open {
    CreateIfMissing,  ///< makes DIR and DIR/jobs (run, campaign create)
    MustExist,        ///< MissingCampaign if DIR holds no store (fit, report, cancel, retry)
  };
  CampaignWriter(const std::string& dir, Open how);
  db::Database& db() { return db_; }

 private:
  struct Prepared {
    Prepared(const std::string& dir, Open how);
  };
  Prepared prepared_;  // members are built in this order: directory, lock, database
  CoordinatorLock lock_;
  db::Database db_;
};

/// Read-only: checks the store's identity and version and writes nothing.
class CampaignReader {
 public:
  explicit CampaignReader(const std::string& dir);
  db::Database& db() { return db_; }

 private:
  struct Prepared {
    explicit Prepared(const std::string& dir);
  };
  Prepared prepared_;
  db::Database db_;
};

}  // namespace beverloo
