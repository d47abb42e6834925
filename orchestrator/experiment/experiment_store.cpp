#include "experiment_store.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/errors.h"

namespace beverloo::experiment {

PreparedImport prepare_import(const std::string& path, const ImportOptions& o) {
  PreparedImport p;
  p.file = read_csv(path);
  const ExperimentFile& f = p.file;
  p.units = resolve_units(f, o.units);
  auto header = [&](const char* key) { return f.header.count(key) ? f.header.at(key) : std::string(); };
  p.series = !o.series.empty() ? o.series : !header("series").empty() ? header("series")
                                                                       : std::filesystem::path(path).stem().string();
  p.provenance = !o.provenance.empty() ? o.provenance : header("provenance");
  if (p.provenance.empty())
    throw ConfigError(path, "does not say whether its data was measured: give the header \"provenance: measured\" "
                            "(or \"simulated\") or --provenance");
  if (p.provenance != "measured" && p.provenance != "simulated")
    throw ConfigError(path + " provenance", "must be \"measured\" or \"simulated\", got \"" + p.provenance + "\"");
  p.source = header("source");
  p.geometry = header("geometry");
  if (o.fit_skip < 0) throw ConfigError("--fit-skip", "must be >= 0");
  if (o.block_exits < 2) throw ConfigError("--block-exits", "must be >= 2");
  p.fit_skip = o.fit_skip;
  p.block_exits = o.block_exits;
  for (const RunData& r : f.runs) {
    FittedRun fr;
    fr.run = &r;
    fr.w = r.w_m / p.units.sigma_avg_m;
    fr.fit = fit_drain(r.exit_t_s, r.n_initial, p.fit_skip, p.block_exits);
    if (fr.fit.ok) {
      // c0 per second times t0: the paper's Q = c0 sqrt(sigma_avg / g_eff)
      fr.Q = fr.fit.c0 * p.units.t0_s;
      fr.Q_err = fr.fit.c0_err * p.units.t0_s;
    }
    p.runs.push_back(fr);
  }
  return p;
}

void store_import(db::Database& db, const PreparedImport& p, bool replace) {
  db::Transaction tx(db);
  db::Statement find = db.prepare("SELECT id FROM experiment_series WHERE name = ?1");
  find.bind(1, p.series);
  if (find.step()) {
    if (!replace)
      throw ConfigError("--series", "a series named \"" + p.series + "\" is already in this campaign; give another " +
                                        "name (--series) or --replace it");
    const std::int64_t old = find.get_int(0);
    // explicit deletes: the store does not switch on foreign-key cascades
    for (const char* sql : {"DELETE FROM experiment_exits WHERE run_id IN (SELECT id FROM experiment_runs WHERE series_id = ?1)",
                            "DELETE FROM experiment_runs WHERE series_id = ?1",
                            "DELETE FROM experiment_fit_results WHERE series_id = ?1",
                            "DELETE FROM experiment_series WHERE id = ?1"}) {
      db::Statement del = db.prepare(sql);
      del.bind(1, old).run();
    }
  }
  db::Statement series = db.prepare(
      "INSERT INTO experiment_series (name, provenance, source, geometry, sigma_avg_m, g_eff_m_s2, t0_s, fit_skip, "
      "block_exits, file_name, file_sha256) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)");
  series.bind(1, p.series).bind(2, p.provenance).bind(3, p.source).bind(4, p.geometry).bind(5, p.units.sigma_avg_m)
      .bind(6, p.units.g_eff_m_s2).bind(7, p.units.t0_s).bind(8, p.fit_skip).bind(9, p.block_exits)
      .bind(10, std::filesystem::path(p.file.path).filename().string()).bind(11, p.file.sha256).run();
  const std::int64_t series_id = db.scalar_int("SELECT last_insert_rowid()");
  db::Statement run = db.prepare(
      "INSERT INTO experiment_runs (series_id, run, w_m, w, n_initial, exits, duration_s, c0_per_s, c0_err_per_s, Q, "
      "Q_err, chi2_red, blocks, message) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)");
  db::Statement exit = db.prepare("INSERT INTO experiment_exits (run_id, k, t_s) VALUES (?1, ?2, ?3)");
  for (const FittedRun& fr : p.runs) {
    const RunData& r = *fr.run;
    run.bind(1, series_id).bind(2, r.name).bind(3, r.w_m).bind(4, fr.w).bind(5, r.n_initial)
        .bind(6, static_cast<std::int64_t>(r.exit_t_s.size())).bind(7, r.exit_t_s.empty() ? 0.0 : r.exit_t_s.back());
    if (fr.fit.ok) {
      run.bind(8, fr.fit.c0).bind(9, fr.fit.c0_err).bind(10, fr.Q).bind(11, fr.Q_err).bind(12, fr.fit.chi2_red)
          .bind(13, fr.fit.blocks).bind_null(14);
    } else {
      for (int c = 8; c <= 13; ++c) run.bind_null(c);
      run.bind(14, fr.fit.message);
    }
    run.run();
    const std::int64_t run_id = db.scalar_int("SELECT last_insert_rowid()");
    for (std::size_t k = 0; k < r.exit_t_s.size(); ++k)
      exit.bind(1, run_id).bind(2, static_cast<std::int64_t>(k)).bind(3, r.exit_t_s[k]).run();
  }
  tx.commit();
}

std::string simulated_drains_csv(const std::vector<SimulatedDrain>& drains, const std::string& series,
                                 const std::string& source, const std::string& geometry, double sigma_avg_m,
                                 double g_eff_m_s2) {
  const double t0 = std::sqrt(sigma_avg_m / g_eff_m_s2);
  std::ostringstream o;
  o.precision(17);
  o << "# beverloo-exits 1\n"
    << "# series: " << series << "\n"
    << "# provenance: simulated\n"
    << "# source: " << source << "\n";
  if (!geometry.empty()) o << "# geometry: " << geometry << "\n";
  o << "# sigma_avg_m: " << sigma_avg_m << "\n# g_eff_m_s2: " << g_eff_m_s2 << "\n"
    << "# simulated by beverloo, not measured: exit times in t0 = sqrt(sigma_avg/g_eff) converted to seconds\n"
    // counts (N after each exit, the run's start first): a drain that ended with particles left
    // keeps its N0, which an exits-only file would take to be the number of exits
    << "run,w_m,t_s,N\n";
  for (const SimulatedDrain& d : drains) {
    int left = d.n_initial;
    o << d.run << "," << d.w * sigma_avg_m << "," << 0.0 << "," << left << "\n";
    for (double t : d.exit_time) o << d.run << "," << d.w * sigma_avg_m << "," << t * t0 << "," << --left << "\n";
  }
  return o.str();
}

}  // namespace beverloo::experiment
