#pragma once
/// \file experiment_csv.h
/// \brief Draining-hopper data files (docs/experiments.md): droplet exits per run, in SI units.
///
///     # beverloo-exits 1
///     # series: oil in water, 45/45 hopper
///     # provenance: measured            (or: simulated, for data made by beverloo)
///     # source: lab notebook 12, camera 0.75 fps
///     # geometry: 45/45
///     # sigma_avg_m: 3.15e-4            mean droplet diameter
///     # g_eff_m_s2: 0.639               or rho_drop_kg_m3 and rho_medium_kg_m3 (and g_m_s2)
///     run,w_m,t_s                       one row per exit; or run,w_m,t_s,N: N in the hopper at t_s
///     a1,5.7e-4,0.00
///
/// A header line is "# key: value" with a one-word key; other lines starting with # are
/// comments. Every problem is a ConfigError naming the file, the line and the column.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace beverloo::experiment {

inline constexpr std::size_t kMaxCsvBytes = 256u << 20;  ///< 256 MiB
inline constexpr double kStandardGravity = 9.80665;      ///< m/s^2
/// A count N of one row: at most this many droplets (no hopper experiment holds more).
inline constexpr double kMaxDroplets = 1e7;
/// Exits of one file in all, counts included: their times are kept in memory (8 bytes each).
inline constexpr std::size_t kMaxExits = 20'000'000;

struct RunData {
  std::string name;
  int first_line = 0;
  double w_m = 0;                ///< orifice width, metres
  int n_initial = 0;             ///< droplets in the hopper at the run's first time
  std::vector<double> exit_t_s;  ///< seconds from the run's first recorded time, sorted
};

struct ExperimentFile {
  std::string path, sha256;
  std::map<std::string, std::string> header;  ///< "# key: value" lines
  bool counts = false;                        ///< the N column was given
  std::vector<RunData> runs;                  ///< in file order
};

/// Reads and checks path (a regular file of at most kMaxCsvBytes).
ExperimentFile read_csv(const std::string& path);
/// The same for text in memory (the fuzzers' entry); `path` names it in messages.
ExperimentFile parse_csv_text(const std::string& text, const std::string& path);

/// The physical constants of a series: from the header, overridden by the command line.
struct Units {
  std::optional<double> sigma_avg_m, g_eff_m_s2, rho_drop_kg_m3, rho_medium_kg_m3, g_m_s2;
};
struct Resolved {
  double sigma_avg_m = 0, g_eff_m_s2 = 0, t0_s = 0;
};
/// sigma_avg and g_eff (given, or g |rho_medium - rho_drop| / rho_drop), t0 = sqrt(sigma/g_eff).
Resolved resolve_units(const ExperimentFile& f, const Units& command_line);

/// A header value as a positive finite number; nullopt if absent; ConfigError naming it if bad.
std::optional<double> header_number(const ExperimentFile& f, const std::string& key);

}  // namespace beverloo::experiment
