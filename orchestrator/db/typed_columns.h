#pragma once
/// \file typed_columns.h
/// \brief Typed SQL columns straight from the engine's two tables:
///  - job parameters (engine/parameters): each a VIRTUAL generated column of `jobs` over the
///    stored canonical job JSON (json_extract, with the row's SQL default where the JSON does not
///    carry the field), the seed excepted (stored: derived when the job gives none); schema
///    0010 turned the columns 0001 and 0003 stored into generated ones;
///  - result fields (engine/protocol/result_fields): the `results` columns of schema 0001 are
///    filled from summary.json by the row (results_insert_sql, bind_result_columns); every other
///    summary field is a VIRTUAL generated column of `results` over summary_json;
///  - the `runs` view, which lists the parameters' and the results' columns in table order.
/// A new parameter or observable therefore needs no hand-written migration: the store adds its
/// column the first time a newer beverloo opens the campaign for writing (inside the migration
/// transaction). Generated columns hold no data, so adding them never rewrites a row.
#include <string>

#include <nlohmann/json.hpp>

#include "database.h"

namespace beverloo {
struct SimConfig;
}

namespace beverloo::db {

/// The SQL of one job's speed over results r: t0 simulated per CPU-minute of a one-thread job
/// (its t_end over its engine wall time; the runs view's t0_per_cpu_minute, job_speed.h).
/// json_extract rather than the generated t_end column: a read-only reader may open a campaign
/// that no newer beverloo has opened for writing yet.
inline constexpr const char* kT0PerCpuMinuteSql = "json_extract(r.summary_json, '$.t_end') * 60.0 / r.wall_seconds";

/// Adds the missing generated columns of `jobs` and `results` and the indexes over parameter
/// columns and, if any column was added or the view is another binary's, rebuilds the `runs`
/// view. Call inside the write transaction of open_store(), after the migrations. Idempotent.
void sync_typed_columns(Database& db);

/// INSERT OR IGNORE of one `jobs` row: ?1 key, ?2 dir, ?3 job_json, ?4 engine_version, ?5 lambda,
/// ?6 dissipation_scale (what is not a parameter), then the stored parameter columns (today the
/// seed alone, ?7); every other parameter column is generated from job_json.
const std::string& jobs_insert_sql();
/// Binds the stored parameter columns (?7 on) from the resolved config: the seed the run uses
/// (derived when the job gives none).
void bind_parameter_columns(Statement& insert, const SimConfig& config);

/// INSERT OR IGNORE of one `results` row: ?1 job_key, ?2 attempt_id, then the stored result
/// fields in table order, then summary_json.
const std::string& results_insert_sql();
/// Binds the stored result fields from a run's summary (?3 on) and the summary text after them.
/// A number the JSON could not hold (inf, NaN: written as null) is stored as +inf; clog_time is
/// NULL unless the run clogged. Throws nlohmann::json::exception for a missing or mistyped field.
void bind_result_columns(Statement& insert, const nlohmann::json& summary, const std::string& summary_text);

}  // namespace beverloo::db
