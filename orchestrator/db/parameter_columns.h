#pragma once
/// \file parameter_columns.h
/// \brief Typed SQL columns for job parameters added after schema 0005, straight from the
/// parameter table (engine/parameters): each is a VIRTUAL generated column of `jobs` over the
/// stored canonical job JSON (json_extract, with the row's SQL default where the JSON does not
/// carry the field), and the `runs` view lists them. A new parameter therefore needs no
/// hand-written migration: the store adds its column the first time a newer beverloo opens the
/// campaign for writing (inside the migration transaction). Generated columns hold no data, so
/// adding them never rewrites a row.
#include "database.h"

namespace beverloo::db {

/// The SQL of one job's speed over results r: t0 simulated per CPU-minute of a one-thread job
/// (its t_end over its engine wall time; the runs view's t0_per_cpu_minute, job_speed.h).
inline constexpr const char* kT0PerCpuMinuteSql = "json_extract(r.summary_json, '$.t_end') * 60.0 / r.wall_seconds";

/// Adds the missing generated columns and, if any were added, rebuilds the `runs` view.
/// Call inside the write transaction of open_store(). Idempotent.
void sync_parameter_columns(Database& db);

}  // namespace beverloo::db
