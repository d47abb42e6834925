#include "migrations.h"

#include "typed_columns.h"

#include "schema_migrations.inc"  // generated: kMigrations[] = {{"0001_init.sql", R"(...)"}, ...}

namespace beverloo::db {

int known_schema_version() { return static_cast<int>(sizeof(kMigrations) / sizeof(kMigrations[0])); }

void check_store(Database& db) {
  const std::int64_t app = db.scalar_int("PRAGMA application_id");
  const std::int64_t version = db.scalar_int("PRAGMA user_version");
  if (app != kApplicationId)
    throw DbError("not a beverloo campaign database (application_id " + std::to_string(app) + ")", SQLITE_MISMATCH);
  if (version > known_schema_version())
    throw DbError("campaign database has schema version " + std::to_string(version) + ", newer than this beverloo (" +
                      std::to_string(known_schema_version()) + "); use a newer beverloo",
                  SQLITE_MISMATCH);
}

void open_store(Database& db) {
  // Identity first, with reads only: another application's database must leave with the
  // bytes it came with (switching it to WAL would rewrite its header).
  {
    const std::int64_t app = db.scalar_int("PRAGMA application_id");
    const std::int64_t version = db.scalar_int("PRAGMA user_version");
    if (app == 0 && version == 0) {
      if (db.scalar_int("SELECT count(*) FROM sqlite_schema") != 0)
        throw DbError("this file is an SQLite database of another application; refusing to touch it", SQLITE_MISMATCH);
    } else {
      check_store(db);
    }
  }
  db.exec("PRAGMA journal_mode=WAL");
  db.exec("PRAGMA synchronous=NORMAL");
  // Off while migrating (it cannot change inside a transaction): a migration may rebuild a table
  // that others reference, as SQLite's ALTER TABLE procedure requires; checked before commit.
  db.exec("PRAGMA foreign_keys=OFF");
  Transaction tx(db);
  const std::int64_t app = db.scalar_int("PRAGMA application_id");
  const std::int64_t version = db.scalar_int("PRAGMA user_version");
  if (app == 0 && version == 0) {
    if (db.scalar_int("SELECT count(*) FROM sqlite_schema") != 0)
      throw DbError("this file is an SQLite database of another application; refusing to touch it", SQLITE_MISMATCH);
    db.exec("PRAGMA application_id=" + std::to_string(kApplicationId));
  } else {
    check_store(db);
  }
  for (int v = static_cast<int>(version); v < known_schema_version(); ++v) {
    db.exec(kMigrations[v].sql);
    db.exec("PRAGMA user_version=" + std::to_string(v + 1));
  }
  sync_typed_columns(db);  // generated columns of parameters and results, the runs view
  if (db.scalar_int("SELECT count(*) FROM pragma_foreign_key_check") != 0)
    throw DbError("a schema migration left dangling references; the database is unchanged", SQLITE_CONSTRAINT);
  tx.commit();
  db.exec("PRAGMA foreign_keys=ON");
}

}  // namespace beverloo::db
