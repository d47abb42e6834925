#include "experiment_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "core/digest.h"
#include "core/errors.h"
#include "core/user_file.h"

namespace beverloo::experiment {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// A whole cell as a finite double, or nullopt.
std::optional<double> to_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

const std::set<std::string> kHeaderKeys = {"series", "provenance", "source", "geometry", "sigma_avg_m",
                                           "g_eff_m_s2", "rho_drop_kg_m3", "rho_medium_kg_m3", "g_m_s2"};

}  // namespace

ExperimentFile read_csv(const std::string& path) { return parse_csv_text(read_user_file(path, kMaxCsvBytes), path); }

ExperimentFile parse_csv_text(const std::string& text_in, const std::string& path) {
  if (text_in.size() > kMaxCsvBytes) throw ConfigError(path, too_large(text_in.size(), kMaxCsvBytes));
  // a spreadsheet's UTF-8 export starts with a byte-order mark: not part of the first line
  const bool bom = text_in.compare(0, 3, "\xEF\xBB\xBF") == 0;
  const std::string& text = bom ? text_in.substr(3) : text_in;
  ExperimentFile f;
  f.path = path;
  f.sha256 = sha256_hex(text);
  std::istringstream lines(text);
  std::string line;
  int n = 0;
  std::vector<std::string> columns;
  int c_run = -1, c_w = -1, c_t = -1, c_n = -1;
  std::set<std::string> finished;  // runs whose rows have ended (a run's rows are contiguous)
  RunData* run = nullptr;
  double last_t = 0, last_n = 0, t_start = 0;
  std::size_t total_exits = 0;
  auto where = [&](const std::string& column) {
    return path + ":" + std::to_string(n) + (column.empty() ? "" : " column " + column);
  };
  while (std::getline(lines, line)) {
    ++n;
    if (line.find('\0') != std::string::npos) throw ConfigError(where(""), "holds a NUL byte: not a text file");
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string body = trim(t.substr(1));
      // the format's version: this reader knows version 1; a newer file is refused, not misread
      if (body.rfind("beverloo-exits", 0) == 0) {
        const std::string version = trim(body.substr(14));
        if (version != "1")
          throw ConfigError(where(""), "format \"beverloo-exits " + version +
                                           "\" is not one this beverloo reads (it reads beverloo-exits 1)");
        continue;
      }
      // "# key: value" with a one-word key is a header line; anything else a comment
      const auto colon = body.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = trim(body.substr(0, colon)), value = trim(body.substr(colon + 1));
      if (key.empty() || key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
                             std::string::npos)
        continue;
      if (!columns.empty()) throw ConfigError(where(""), "header line \"" + key + "\" after the column names");
      if (!kHeaderKeys.count(key))
        throw ConfigError(where(""), "unknown header key \"" + key + "\" (known: series, provenance, source, geometry, "
                                     "sigma_avg_m, g_eff_m_s2, rho_drop_kg_m3, rho_medium_kg_m3, g_m_s2)");
      if (f.header.count(key)) throw ConfigError(where(""), "header key \"" + key + "\" given twice");
      f.header[key] = value;
      continue;
    }
    const std::vector<std::string> cells = split(t);
    if (columns.empty()) {
      columns = cells;
      for (std::size_t k = 0; k < columns.size(); ++k) {
        const std::string& c = columns[k];
        int* slot = c == "run" ? &c_run : c == "w_m" ? &c_w : c == "t_s" ? &c_t : c == "N" ? &c_n : nullptr;
        if (!slot) throw ConfigError(where(""), "unknown column \"" + c + "\" (columns: run, w_m, t_s and optionally N)");
        if (*slot >= 0) throw ConfigError(where(""), "column \"" + c + "\" given twice");
        *slot = static_cast<int>(k);
      }
      if (c_run < 0 || c_w < 0 || c_t < 0)
        throw ConfigError(where(""), "the column names must include run, w_m and t_s (and N for counts), got \"" + t + "\"");
      f.counts = c_n >= 0;
      continue;
    }
    if (cells.size() != columns.size())
      throw ConfigError(where(""), "has " + std::to_string(cells.size()) + " cells, the header names " +
                                       std::to_string(columns.size()));
    const std::string& name = cells[c_run];
    if (name.empty()) throw ConfigError(where("run"), "is empty");
    const auto w = to_number(cells[c_w]);
    if (!w || *w <= 0) throw ConfigError(where("w_m"), "must be a positive number of metres, got \"" + cells[c_w] + "\"");
    const auto time = to_number(cells[c_t]);
    if (!time || *time < 0) throw ConfigError(where("t_s"), "must be a number of seconds >= 0, got \"" + cells[c_t] + "\"");
    std::optional<double> count;
    if (f.counts) {
      count = to_number(cells[c_n]);
      if (!count || *count < 0 || *count != std::floor(*count) || *count > kMaxDroplets)
        throw ConfigError(where("N"), "must be a whole number of droplets from 0 to " +
                                          std::to_string(static_cast<long long>(kMaxDroplets)) + ", got \"" + cells[c_n] + "\"");
    }
    if (!run || run->name != name) {
      if (finished.count(name))
        throw ConfigError(where("run"), "run \"" + name + "\" continues after other runs: a run's rows must be together");
      if (run) finished.insert(run->name);
      f.runs.push_back(RunData{name, n, *w, 0, {}});
      run = &f.runs.back();
      t_start = *time;
      last_t = *time;
      if (f.counts) {
        run->n_initial = static_cast<int>(*count);
        last_n = *count;
        continue;  // the first count is the start, not an exit
      }
    }
    if (*w != run->w_m)
      throw ConfigError(where("w_m"), "run \"" + name + "\" changes its orifice width (" + cells[c_w] + " after " +
                                          std::to_string(run->w_m) + " m)");
    if (*time < last_t)
      throw ConfigError(where("t_s"), "time " + cells[c_t] + " s goes back (the run was at " + std::to_string(last_t) +
                                          " s): times must not decrease");
    last_t = *time;
    if (f.counts) {
      if (*count > last_n)
        throw ConfigError(where("N"), "N rises from " + std::to_string(static_cast<long long>(last_n)) + " to " +
                                          cells[c_n] + ": a draining hopper's count only falls");
      // the exits this row stands for, counted against the file's limit before any is stored
      total_exits += static_cast<std::size_t>(last_n - *count);
      if (total_exits > kMaxExits)
        throw ConfigError(where("N"), "the file stands for more than " + std::to_string(kMaxExits) + " exits in all");
      for (double k = *count; k < last_n; k += 1) run->exit_t_s.push_back(*time - t_start);
      last_n = *count;
    } else {
      if (++total_exits > kMaxExits)
        throw ConfigError(where(""), "the file holds more than " + std::to_string(kMaxExits) + " exits in all");
      run->exit_t_s.push_back(*time - t_start);
      run->n_initial = static_cast<int>(run->exit_t_s.size());
    }
  }
  if (columns.empty()) throw ConfigError(path, "has no column names (run,w_m,t_s[,N]) and no data");
  if (f.runs.empty()) throw ConfigError(path, "has no data rows");
  return f;
}

std::optional<double> header_number(const ExperimentFile& f, const std::string& key) {
  const auto it = f.header.find(key);
  if (it == f.header.end()) return std::nullopt;
  const auto v = to_number(it->second);
  if (!v || *v <= 0) throw ConfigError(f.path + " header " + key, "must be a positive number, got \"" + it->second + "\"");
  return v;
}

Resolved resolve_units(const ExperimentFile& f, const Units& cl) {
  auto pick = [&](const std::optional<double>& given, const std::string& key, const char* option) {
    if (given) {
      if (!(*given > 0) || !std::isfinite(*given)) throw ConfigError(option, "must be a positive number");
      return given;
    }
    return header_number(f, key);
  };
  Resolved r;
  const auto sigma = pick(cl.sigma_avg_m, "sigma_avg_m", "--sigma-m");
  if (!sigma) throw ConfigError(f.path, "no mean droplet diameter: give the header sigma_avg_m or --sigma-m (metres)");
  r.sigma_avg_m = *sigma;
  // The command line overrides the header, the effective gravity as a whole: --g-eff on the line
  // sets aside the header's densities, a density on the line the header's g_eff. Only one
  // source giving both ways is a contradiction.
  const bool line_g_eff = cl.g_eff_m_s2.has_value(), line_rho = cl.rho_drop_kg_m3 || cl.rho_medium_kg_m3;
  if (line_g_eff && line_rho)
    throw ConfigError("--g-eff", "give either --g-eff or the two densities (--rho-drop, --rho-medium), not both");
  std::optional<double> g_eff, rho_d, rho_m;
  if (!line_rho) g_eff = pick(cl.g_eff_m_s2, "g_eff_m_s2", "--g-eff");
  if (!line_g_eff) {
    rho_d = pick(cl.rho_drop_kg_m3, "rho_drop_kg_m3", "--rho-drop");
    rho_m = pick(cl.rho_medium_kg_m3, "rho_medium_kg_m3", "--rho-medium");
  }
  const auto g = pick(cl.g_m_s2, "g_m_s2", "--g");
  if (g_eff && (rho_d || rho_m))
    throw ConfigError(f.path, "give either g_eff or the two densities, not both (g_eff = g |rho_medium - rho_drop| / rho_drop)");
  if (g_eff) {
    r.g_eff_m_s2 = *g_eff;
  } else {
    if (!rho_d || !rho_m)
      throw ConfigError(f.path, "no effective gravity: give g_eff_m_s2 (--g-eff) or rho_drop_kg_m3 and rho_medium_kg_m3 "
                                "(--rho-drop, --rho-medium)");
    if (*rho_d == *rho_m) throw ConfigError(f.path, "rho_drop equals rho_medium: no buoyancy, g_eff = 0");
    // the paper's g_eff = g (rho_water - rho_oil) / rho_oil; a sinking drop's is the same magnitude
    r.g_eff_m_s2 = g.value_or(kStandardGravity) * std::fabs(*rho_m - *rho_d) / *rho_d;
  }
  r.t0_s = std::sqrt(r.sigma_avg_m / r.g_eff_m_s2);
  return r;
}

}  // namespace beverloo::experiment
