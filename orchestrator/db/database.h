#pragma once
/// \file database.h
/// \brief A thin, boring SQLite layer: a connection, prepared statements that reset themselves,
/// RAII transactions that roll back unless committed, and one error type.
#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace beverloo::db {

class DbError : public std::runtime_error {
 public:
  DbError(const std::string& what, int code) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

class Statement;

class Database {
 public:
  /// ReadOnlyImmutable: for a directory we cannot write, where SQLite could not create the
  /// WAL index (-shm) a reader of a WAL database needs; opened as immutable (nobody can write
  /// the database there either: a writer needs the same directory).
  enum class Mode { ReadWrite, ReadOnly, ReadOnlyImmutable };
  /// Opens (ReadWrite: creates) the file; sets extended result codes and a busy timeout.
  Database(const std::string& path, Mode mode);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  void exec(const std::string& sql);
  Statement prepare(const std::string& sql);
  std::int64_t last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }
  int changes() const { return sqlite3_changes(db_); }
  sqlite3* handle() { return db_; }
  /// Single integer result of a query (e.g. a PRAGMA or COUNT(*)).
  std::int64_t scalar_int(const std::string& sql);
  /// True if the schema has this table (a read-only reader of an older store may lack newer ones).
  bool has_table(const std::string& name) {
    return scalar_int("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = '" + name + "'") > 0;
  }
  [[noreturn]] void fail(const std::string& context, int rc) const;

 private:
  sqlite3* db_ = nullptr;
};

/// A prepared statement; bind parameters are 1-based. Reset and cleared on every use.
class Statement {
 public:
  Statement(Database& db, sqlite3_stmt* st) : db_(&db), st_(st) {}
  Statement(Statement&& o) noexcept : db_(o.db_), st_(o.st_) { o.st_ = nullptr; }
  Statement(const Statement&) = delete;
  ~Statement() { sqlite3_finalize(st_); }

  Statement& bind(int i, std::int64_t v);
  Statement& bind(int i, int v) { return bind(i, static_cast<std::int64_t>(v)); }
  Statement& bind(int i, double v);
  Statement& bind(int i, const std::string& v);
  Statement& bind(int i, const char* v) { return bind(i, std::string(v)); }
  Statement& bind_null(int i);
  Statement& bind(int i, std::optional<double> v) { return v ? bind(i, *v) : bind_null(i); }
  /// Steps once: true if a row is available.
  bool step();
  /// Runs to completion (for statements without results).
  void run();
  void reset();
  int columns() const { return sqlite3_column_count(st_); }
  std::string column_name(int i) const { return sqlite3_column_name(st_, i); }
  int column_type(int i) const { return sqlite3_column_type(st_, i); }
  std::int64_t get_int(int i) const { return sqlite3_column_int64(st_, i); }
  double get_double(int i) const { return sqlite3_column_double(st_, i); }
  std::string get_text(int i) const;
  bool is_null(int i) const { return sqlite3_column_type(st_, i) == SQLITE_NULL; }
  bool readonly() const { return sqlite3_stmt_readonly(st_) != 0; }
  sqlite3_stmt* handle() { return st_; }

 private:
  Database* db_;
  sqlite3_stmt* st_;
  bool stepping_ = false;
};

/// BEGIN IMMEDIATE on construction (takes the write lock at once); ROLLBACK in the destructor
/// unless commit() was called.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace beverloo::db
