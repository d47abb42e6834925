#include "database.h"

#include <cstdio>

namespace beverloo::db {

namespace {
/// "file:" URI of a path: the characters a URI gives meaning to, percent-encoded.
std::string file_uri(const std::string& path) {
  std::string uri = "file:";
  for (unsigned char c : path) {
    if (c == '%' || c == '?' || c == '#' || c < 0x20 || c >= 0x7f) {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", c);
      uri += b;
    } else {
      uri += static_cast<char>(c);
    }
  }
  return uri;
}
}  // namespace

Database::Database(const std::string& path, Mode mode) {
  int flags = mode == Mode::ReadWrite ? SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE : SQLITE_OPEN_READONLY;
  std::string name = path;
  if (mode == Mode::ReadOnlyImmutable) {
    name = file_uri(path) + "?immutable=1";
    flags |= SQLITE_OPEN_URI;
  }
  const int rc = sqlite3_open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw DbError("cannot open " + path + ": " + msg, rc);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, 10000);
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::fail(const std::string& context, int rc) const {
  throw DbError(context + ": " + sqlite3_errmsg(db_) + " (code " + std::to_string(rc) + ")", rc);
}

void Database::exec(const std::string& sql) {
  char* err = nullptr;
  const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err);
  if (rc != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    throw DbError(msg + " (code " + std::to_string(rc) + ")", rc);
  }
}

Statement Database::prepare(const std::string& sql) {
  sqlite3_stmt* st = nullptr;
  const int rc = sqlite3_prepare_v2(db_, sql.c_str(), static_cast<int>(sql.size()), &st, nullptr);
  if (rc != SQLITE_OK) fail("prepare \"" + sql.substr(0, 80) + "\"", rc);
  return Statement(*this, st);
}

std::int64_t Database::scalar_int(const std::string& sql) {
  Statement st = prepare(sql);
  if (!st.step()) fail("no row from " + sql, SQLITE_ERROR);
  return st.get_int(0);
}

Statement& Statement::bind(int i, std::int64_t v) {
  reset();
  if (int rc = sqlite3_bind_int64(st_, i, v); rc != SQLITE_OK) db_->fail("bind", rc);
  return *this;
}
Statement& Statement::bind(int i, double v) {
  reset();
  if (int rc = sqlite3_bind_double(st_, i, v); rc != SQLITE_OK) db_->fail("bind", rc);
  return *this;
}
Statement& Statement::bind(int i, const std::string& v) {
  reset();
  if (int rc = sqlite3_bind_text(st_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT); rc != SQLITE_OK)
    db_->fail("bind", rc);
  return *this;
}
Statement& Statement::bind_null(int i) {
  reset();
  if (int rc = sqlite3_bind_null(st_, i); rc != SQLITE_OK) db_->fail("bind", rc);
  return *this;
}

void Statement::reset() {
  // only between uses: binding the next parameter of the same use must keep the earlier ones
  if (stepping_) {
    sqlite3_reset(st_);
    sqlite3_clear_bindings(st_);
    stepping_ = false;
  }
}

bool Statement::step() {
  stepping_ = true;
  const int rc = sqlite3_step(st_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  db_->fail(std::string("step \"") + std::string(sqlite3_sql(st_)).substr(0, 80) + "\"", rc);
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

std::string Statement::get_text(int i) const {
  const unsigned char* t = sqlite3_column_text(st_, i);
  return t ? std::string(reinterpret_cast<const char*>(t), sqlite3_column_bytes(st_, i)) : std::string();
}

Transaction::Transaction(Database& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }
Transaction::~Transaction() {
  if (!done_) {
    try {
      db_.exec("ROLLBACK");
    } catch (...) {
    }
  }
}
void Transaction::commit() {
  db_.exec("COMMIT");
  done_ = true;
}

}  // namespace beverloo::db
