#pragma once
/// \file result_fields.h
/// \brief The one table of a run's scalar results (observables and run statistics), as
/// parameters.h is the one table of a job's inputs.
///
/// Each row names a field of RunResult once: its type, unit, meaning, and where it goes. From
/// the table come
///  - summary.json (RunResult::summary_json) and the /result and /run attributes of result.h5
///    (engine/io/result_file.cpp);
///  - the campaign database: the `results` columns the store fills (the ones of schema 0001),
///    a generated column over results.summary_json for every other summary field (added when a
///    newer beverloo opens the campaign, like the parameters' columns), and the result columns of
///    the `runs` view (orchestrator/db);
///  - the table of docs/database.md (`beverloo params --results --format markdown`, checked by a
///    test).
/// Adding an observable = its member in RunResult, the code that measures it, one row here, its
/// test. The long series (exits, rate, profile) and the draining fit have their own layout.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace beverloo {

struct RunResult;

enum class ResultType { Real, Integer, Boolean, Text };

/// Where result.h5 keeps a field: the physics result, the run's statistics (differ between
/// machines), or neither (dt and seed are in /parameters; a few fields are summary-only).
enum class ResultGroup { Result, Run, None };

/// How the campaign database holds a field.
enum class ResultSql {
  Column,     ///< a column of `results` since schema 0001, filled by the store
  Generated,  ///< a generated column over results.summary_json (added by the store when missing)
  None,       ///< not in the database (not in summary.json)
};

using ResultValue = std::variant<double, std::int64_t, std::uint64_t, bool, std::string>;

struct ResultField {
  std::string_view name;  ///< as summary.json, result.h5 and SQL spell it
  ResultType type;
  std::string_view unit;  ///< "-" for pure numbers; code units are those of units.h (t0, sigma_avg)
  std::string_view doc;   ///< one line
  ResultGroup h5_group;
  bool in_summary;        ///< a key of summary.json
  ResultSql sql;
  bool in_runs_view;      ///< a column of the `runs` view (in table order)
  /// the database column is NULL unless the run clogged (clog_time: -1 means "none" in the files)
  bool null_unless_clogged = false;
  ResultValue (*get)(const RunResult&) = nullptr;

  /// SQL type of the column: REAL, INTEGER (also Boolean: 0/1) or TEXT.
  std::string_view sql_type() const;
};

/// "/result", "/run" or "" (result.h5's group); "column", "generated" or "" (the database).
std::string_view h5_group_name(ResultGroup g);
std::string_view sql_kind_name(ResultSql s);

/// Every scalar result field, in the order of docs/database.md.
const std::vector<ResultField>& result_fields();
/// The row of a name, or nullptr.
const ResultField* find_result_field(std::string_view name);
/// The results table of docs/database.md.
std::string result_fields_markdown();

}  // namespace beverloo
