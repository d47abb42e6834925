#include "campaign_dir.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "orchestrator/db/migrations.h"
#include "store.h"  // host_name

namespace beverloo {
namespace fs = std::filesystem;

namespace campaign_dir {
std::string database_path(const std::string& dir) { return (fs::path(dir) / kDatabaseFile).string(); }
std::string report_path(const std::string& dir) { return (fs::path(dir) / kReportDir).string(); }
std::string job_dir_relative(const std::string& job_key) { return std::string(kJobsDir) + "/" + job_key.substr(0, 16); }
bool holds_campaign(const std::string& dir) {
  std::error_code ec;
  return fs::is_regular_file(database_path(dir), ec);
}
void check_store_file(const std::string& dir) {
  const std::string path = database_path(dir);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) return;
  if (!fs::is_regular_file(st))
    throw ConfigError(path, "is not a regular file (a directory, FIFO or device): not a campaign database; refusing to touch it");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot be read");
  unsigned char h[100] = {};
  in.read(reinterpret_cast<char*>(h), sizeof h);
  const std::streamsize got = in.gcount();
  if (got == 0) return;  // an empty file: SQLite makes a new database of it
  static const char kMagic[16] = {'S', 'Q', 'L', 'i', 't', 'e', ' ', 'f', 'o', 'r', 'm', 'a', 't', ' ', '3', '\0'};
  if (got < 100 || std::memcmp(h, kMagic, 16) != 0)
    throw ConfigError(path, "is not an SQLite database (no SQLite header): not a beverloo campaign; refusing to touch it");
  auto be32 = [&](int at) {
    return (std::uint32_t(h[at]) << 24) | (std::uint32_t(h[at + 1]) << 16) | (std::uint32_t(h[at + 2]) << 8) | h[at + 3];
  };
  const std::uint32_t schema_cookie = be32(40), user_version = be32(60), application_id = be32(68);
  if (application_id != db::kApplicationId && (application_id != 0 || user_version != 0 || schema_cookie != 0))
    throw ConfigError(path, "is an SQLite database of another application (application_id " +
                                std::to_string(application_id) + "), not a beverloo campaign; refusing to touch it");
  if (static_cast<std::int64_t>(user_version) > db::known_schema_version())
    throw ConfigError(path, "has campaign schema version " + std::to_string(user_version) + ", newer than this beverloo (" +
                                std::to_string(db::known_schema_version()) + "); use a newer beverloo");
}

}  // namespace campaign_dir

MissingCampaign::MissingCampaign(const std::string& dir)
    : std::runtime_error(dir + " holds no campaign (no " + campaign_dir::kDatabaseFile +
                         "); create one with `beverloo run SWEEP --dir " + dir + "`") {}

CoordinatorLock::CoordinatorLock(const std::string& dir) {
  const std::string path = (fs::path(dir) / campaign_dir::kLockFile).string();
  fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);  // CLOEXEC: workers must not inherit it
  if (fd_ < 0) throw IoError("cannot open " + path);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    std::ifstream in(path);
    std::string holder;
    std::getline(in, holder);
    ::close(fd_);
    fd_ = -1;
    throw CampaignBusy("another coordinator is running this campaign (" + holder + "); wait for it or stop it");
  }
  // a dead holder's lock is gone with its process: we own it now; say who we are
  std::ostringstream me;
  me << "host " << host_name() << ", pid " << ::getpid() << ", since " << std::time(nullptr);
  const std::string text = me.str() + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) < 0) { /* informational only */ }
}

CoordinatorLock::~CoordinatorLock() {
  if (fd_ >= 0) ::close(fd_);
}

CampaignWriter::Prepared::Prepared(const std::string& dir, Open how) {
  if (how == Open::MustExist && !campaign_dir::holds_campaign(dir)) throw MissingCampaign(dir);
  campaign_dir::check_store_file(dir);  // before the directory, the lock or SQLite touch anything
  if (how == Open::CreateIfMissing) {
    std::error_code ec;
    fs::create_directories(dir, ec);  // jobs/ once the store is known to be ours
    if (ec) throw IoError("cannot create " + dir + ": " + ec.message());
  }
}

CampaignWriter::CampaignWriter(const std::string& dir, Open how)
    : prepared_(dir, how), lock_(dir), db_(campaign_dir::database_path(dir), db::Database::Mode::ReadWrite) {
  db::open_store(db_);
  std::error_code ec;
  fs::create_directories(fs::path(dir) / campaign_dir::kJobsDir, ec);
  if (ec) throw IoError("cannot create " + (fs::path(dir) / campaign_dir::kJobsDir).string() + ": " + ec.message());
}

CampaignReader::Prepared::Prepared(const std::string& dir) {
  if (!campaign_dir::holds_campaign(dir)) throw MissingCampaign(dir);
  campaign_dir::check_store_file(dir);
}

namespace {
db::Database::Mode reader_mode(const std::string& dir) {
  // a directory we cannot write: SQLite could not make the WAL index there (nor could a writer)
  return ::access(dir.c_str(), W_OK) == 0 ? db::Database::Mode::ReadOnly : db::Database::Mode::ReadOnlyImmutable;
}
}  // namespace

CampaignReader::CampaignReader(const std::string& dir)
    : prepared_(dir), db_(campaign_dir::database_path(dir), reader_mode(dir)) {
  db::check_store(db_);
}

}  // namespace beverloo
