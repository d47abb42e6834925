#pragma once
/// \file experiment_store.h
/// \brief Experiment series in the campaign database (schema/0006_experiments.sql): an
/// imported file becomes one series; each run is fitted with the engine's draining-hopper fit
/// (engine/protocol/drain_fit), in seconds, and stored with Q = c0 t0. And the way back for
/// test data: a simulated drain written as such a file, labelled as simulated.
#include <string>
#include <vector>

#include "engine/protocol/drain_fit.h"
#include "orchestrator/db/database.h"
#include "orchestrator/experiment/experiment_csv.h"

namespace beverloo::experiment {

struct ImportOptions {
  std::string series;      ///< name; default: the header's "series", else the file's name
  std::string provenance;  ///< "measured" or "simulated"; default: the header's (required)
  Units units;             ///< command-line values, overriding the header's
  int fit_skip = 100;
  int block_exits = 10;
  bool replace = false;    ///< replace a series of the same name
};

struct FittedRun {
  const RunData* run = nullptr;
  double w = 0;  ///< sigma_avg
  DrainFit fit;  ///< c0 per second
  double Q = 0, Q_err = 0;
};

/// Everything an import decides before it writes: checked and fitted, nothing stored yet.
struct PreparedImport {
  ExperimentFile file;
  Resolved units;
  std::string series, provenance, source, geometry;
  int fit_skip = 100, block_exits = 10;
  std::vector<FittedRun> runs;
};

/// Reads, checks and fits; throws ConfigError naming the file, line, column or option.
PreparedImport prepare_import(const std::string& path, const ImportOptions& o);

/// Stores a prepared import in one transaction. A series of the same name is refused
/// (ConfigError) unless o.replace.
void store_import(db::Database& db, const PreparedImport& p, bool replace);

/// One simulated drain as CSV rows of a file (run name, its exits converted to SI).
struct SimulatedDrain {
  std::string run;
  double w = 0;                   ///< sigma_avg
  std::vector<double> exit_time;  ///< t0
  int n_initial = 0;              ///< particles at the start (more than the exits if some stayed)
};
/// The text of a data file holding simulated drains, with the header saying they are simulated.
std::string simulated_drains_csv(const std::vector<SimulatedDrain>& drains, const std::string& series,
                                 const std::string& source, const std::string& geometry, double sigma_avg_m,
                                 double g_eff_m_s2);

}  // namespace beverloo::experiment
