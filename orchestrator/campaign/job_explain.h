#pragma once
/// \file job_explain.h
/// \brief "Why did this rerun?" (`beverloo campaign explain`): whether a job is in a campaign's
/// store and done, and if not, the stored job nearest to it and the fields in which they
/// differ. Job identity is content-addressed (the canonical job without the settings that cannot
/// change a result, and the engine version): any differing field, or another engine version,
/// is a new job.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/config.h"
#include "orchestrator/db/database.h"

namespace beverloo {

struct FieldDifference {
  std::string field;        ///< dotted path, e.g. "dp.K_l" or "run.t_max"
  std::string asked, stored;  ///< the values as JSON text; "(absent)" where a side lacks it
};

struct StoredJob {
  std::string key, state, engine_version, result_status;  ///< result_status "" without a result
  double Q = 0, Q_err = 0;
};

struct JobExplanation {
  std::string key;                    ///< the job asked about
  std::optional<StoredJob> found;     ///< the job itself, if the store has it
  std::optional<StoredJob> nearest;   ///< else (or if it is not done) the nearest done job
  std::vector<FieldDifference> differences;  ///< between the job and `nearest` (identity fields only)
  bool only_engine_differs = false;   ///< nearest has the same fields but another engine version
  long long stored_jobs = 0;          ///< jobs compared
};

/// The job given as its canonical JSON (SimConfig::to_json) and key, against every stored job.
/// `identity_free`: the dotted paths that are not part of the identity (checkpoint cadence, skin, ...).
JobExplanation explain_job(db::Database& db, const std::string& key, const nlohmann::json& job,
                           const std::vector<std::string>& identity_free);

/// The stored job whose key is `key_or_prefix` (at least 8 hex digits; unique); throws
/// std::invalid_argument naming why not.
std::pair<std::string, nlohmann::json> find_stored_job(db::Database& db, const std::string& key_or_prefix);

/// The dotted paths of c's canonical job that are not part of its identity (checkpoint cadence,
/// trajectory output, skin, ...: the parameter rows with in_key = false).
std::vector<std::string> identity_free_paths(const SimConfig& c);

/// Every leaf of j as dotted path -> JSON text (arrays are leaves).
std::vector<std::pair<std::string, std::string>> flatten_json(const nlohmann::json& j);

}  // namespace beverloo
