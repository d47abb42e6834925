#pragma once
/// \file migrations.h
/// \brief The campaign store's schema: numbered SQL files in schema/, embedded at build time and
/// applied in order inside one BEGIN IMMEDIATE ... COMMIT, which also bumps PRAGMA user_version.
#include <string>

#include "database.h"

namespace beverloo::db {

inline constexpr std::int64_t kApplicationId = 0x42564C4F;  // "BVLO"

/// Opens a campaign database read-write, creating and migrating it as needed; WAL mode.
/// Refuses a file that belongs to another application or has a newer schema than this binary.
void open_store(Database& db);
/// The schema version this binary knows (the number of embedded migrations).
int known_schema_version();
/// For read-only openers: checks application_id and version without changing anything.
void check_store(Database& db);

}  // namespace beverloo::db
