#pragma once
/// \file sweep.h
/// \brief The sweep language (docs/sweeps.md, schema/sweep.schema.json): a JSON file that
/// expands into jobs. Deterministic: the same file always gives the same jobs in the same order.
///
///   {"name": "...", "comment": "...",
///    "base":    {engine parameters shared by every job},
///    "run":     {run controls merged into every job's "run"},
///    "sweep":   node,      node := {"product": [node...]} | {"zip": [node...]} | {"union": [node...]}
///                                 | {param: values, ...}  (several params: their product)
///               values := [v...] | {"values": [...]} | {"linspace": [a, b, n]}
///                        | {"logspace": [a, b, n]} (10^a .. 10^b) | {"geomspace": [a, b, n]} | v
///    "derived": {param: "expression over other parameters", ...},
///    "where":   ["expression", ...]   (a point is kept where every expression is nonzero),
///    "replicas": n}
///
/// lambda = zeta/mu with the default parametrisation of physics.md 8 (dissipation_scale s = 1;
/// derived::on_lambda_axis in engine/parameters.h, the one definition):
/// finite lambda > 0: zeta = s/sqrt(10), mu = zeta/lambda; lambda = 0: zeta = 0, mu = 10 s sqrt(10);
/// lambda = "inf": mu = 0, zeta = s/sqrt(10). A sweep that sets zeta or mu itself (an axis or a
/// derived expression) keeps them: lambda is then only a label.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/config.h"

namespace beverloo {

/// A sweep error: "path: value: rule". Exit code 2.
class SweepError : public std::runtime_error {
 public:
  SweepError(const std::string& path, const std::string& message)
      : std::runtime_error(path + ": " + message), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct JobSpec {
  SimConfig config;
  std::string key;            ///< sha256 hex of the canonical job + engine version
  nlohmann::json job;         ///< the canonical resolved job (what the engine runs)
  nlohmann::json point;       ///< this point's own parameters (sweep axes, derived, lambda, replica)
  std::optional<double> lambda, dissipation_scale;
};

struct Sweep {
  std::string name, comment;
  nlohmann::json source;  ///< the file as parsed
  /// The file it was read from (load), empty when parsed from JSON: the errors of load() and
  /// expand() then start with it, "FILE: FIELD: reason", so a user with several sweeps open
  /// sees which one is wrong.
  std::string file;
  /// Parses and checks the structure; throws SweepError.
  static Sweep parse(const nlohmann::json& j, const std::string& default_name = "sweep");
  /// Reads and parses a sweep file (named after the file unless it says otherwise); the file's
  /// text, which identifies the campaign, goes to *text if given.
  static Sweep load(const std::string& path, std::string* text = nullptr);
  /// All jobs, each validated by the engine's own rules; throws SweepError naming the path.
  std::vector<JobSpec> expand() const;

 private:
  std::vector<JobSpec> expand_points() const;
};

/// The job key: sha256 of the canonical job (without settings that cannot change the result:
/// checkpoint cadence, trajectory output) and the engine version.
std::string job_key(const SimConfig& c);

}  // namespace beverloo
