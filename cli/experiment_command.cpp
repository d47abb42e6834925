// `beverloo experiment import FILE --dir D` (measured droplet exits into a campaign) and
// `beverloo experiment export-drain JOB_DIR... -o FILE` (a simulated drain as such a file,
// labelled simulated): docs/experiments.md.
#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "core/atomic_file.h"
#include "engine/io/job_output.h"
#include "guarded.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "orchestrator/experiment/experiment_store.h"
#include "core/text_escape.h"
#include "core/version.h"

namespace beverloo {
namespace {

struct ImportArgs {
  std::string file, dir;
  experiment::ImportOptions o;
  double sigma = 0, g_eff = 0, rho_drop = 0, rho_medium = 0;
};

int import_command(ImportArgs a) {
  auto given = [](double v) { return v != 0 ? std::optional<double>(v) : std::nullopt; };
  a.o.units.sigma_avg_m = given(a.sigma);
  a.o.units.g_eff_m_s2 = given(a.g_eff);
  a.o.units.rho_drop_kg_m3 = given(a.rho_drop);
  a.o.units.rho_medium_kg_m3 = given(a.rho_medium);
  // everything is read, checked and fitted before the campaign is touched: a bad file changes nothing
  const experiment::PreparedImport p = experiment::prepare_import(a.file, a.o);
  CampaignWriter writer(a.dir, CampaignWriter::Open::CreateIfMissing);
  experiment::store_import(writer.db(), p, a.o.replace);
  std::printf("series %s (%s): sigma_avg = %.4g m, g_eff = %.4g m/s^2, t0 = %.4g s; fit of dN/dt = -c0 sqrt(N) "
              "without the first and last %d exits, blocks of %d\n",
              terminal_safe(p.series).c_str(), terminal_safe(p.provenance).c_str(), p.units.sigma_avg_m, p.units.g_eff_m_s2, p.units.t0_s, p.fit_skip,
              p.block_exits);
  int fitted = 0;
  for (const experiment::FittedRun& r : p.runs) {
    if (r.fit.ok) {
      ++fitted;
      std::printf("  run %-12s w = %6.3f sigma_avg  N0 = %5d  c0 = %.4g +- %.2g /s  Q = %.4g +- %.2g\n",
                  terminal_safe(r.run->name).c_str(), r.w, r.run->n_initial, r.fit.c0, r.fit.c0_err, r.Q, r.Q_err);
    } else {
      std::printf("  run %-12s w = %6.3f sigma_avg  N0 = %5d  no fit: %s\n", terminal_safe(r.run->name).c_str(), r.w,
                  r.run->n_initial, terminal_safe(r.fit.message).c_str());
    }
  }
  std::printf("stored %zu runs (%d fitted) in %s; `beverloo fit %s` fits Q = C (w - k)^beta to them\n", p.runs.size(),
              fitted, terminal_safe(campaign_dir::database_path(a.dir)).c_str(), terminal_safe(a.dir).c_str());
  return exit_code::kOk;
}

struct ExportArgs {
  std::vector<std::string> jobs;
  std::string out, series = "simulated drain", geometry;
  double sigma = 0, g_eff = 0;
};

int export_command(const ExportArgs& a) {
  if (!(a.sigma > 0) || !std::isfinite(a.sigma))
    throw ConfigError("--sigma-m", "the droplet diameter to convert to, in metres, is required (a finite number > 0)");
  if (!(a.g_eff > 0) || !std::isfinite(a.g_eff))
    throw ConfigError("--g-eff", "the effective gravity to convert to, in m/s^2, is required (a finite number > 0)");
  if (!std::isfinite(std::sqrt(a.sigma / a.g_eff)) || !(std::sqrt(a.sigma / a.g_eff) > 0))
    throw ConfigError("--sigma-m", "with this --g-eff the time unit sqrt(sigma_avg / g_eff) is not a finite number > 0");
  // a header value is one line of text: a line break would forge a header line (a provenance)
  for (const auto& [option, value] : {std::pair{"--series", &a.series}, std::pair{"--geometry", &a.geometry}})
    for (unsigned char c : *value)
      if (c < 0x20 || c == 0x7F)
        throw ConfigError(option, "\"" + terminal_safe(*value) + "\": must be one line without control characters");
  std::vector<experiment::SimulatedDrain> drains;
  std::string keys;
  for (const std::string& dir : a.jobs) {
    const job_output::DrainRecord d = job_output::read_drain(dir);
    // the run's name: its width and its job directory (a campaign's is the job key's start)
    char name[48];
    std::snprintf(name, sizeof name, "w%g-", d.w);
    std::string job = std::filesystem::path(dir).filename().string();
    if (job.empty()) job = std::filesystem::path(dir).parent_path().filename().string();
    // a row's first field: only characters that need no quoting in CSV and mean nothing in it
    for (char& c : job)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
    std::string run = name + job.substr(0, 12);
    // each run its own name: two jobs whose directories share a start (or one given twice)
    // would otherwise be one run whose time goes back
    for (int k = 2; std::any_of(drains.begin(), drains.end(), [&](const auto& o) { return o.run == run; }); ++k)
      run = name + job.substr(0, 12) + "-" + std::to_string(k);
    if (static_cast<std::size_t>(d.n_initial) < d.exit_time.size())
      throw IoError(dir + ": the drain's result has more exits (" + std::to_string(d.exit_time.size()) +
                    ") than particles (" + std::to_string(d.n_initial) + ")");
    drains.push_back({run, d.w, d.exit_time, d.n_initial});
    if (!std::isfinite(d.w * a.sigma))
      throw ConfigError("--sigma-m", "the orifice width w = " + std::to_string(d.w) + " in metres is not a finite number");
  }
  const std::string source = "beverloo " BEVERLOO_VERSION " draining-hopper simulations (" +
                             std::to_string(drains.size()) + " jobs), not a measurement";
  write_text_atomically(a.out, experiment::simulated_drains_csv(drains, a.series, source, a.geometry, a.sigma, a.g_eff));
  std::printf("wrote %zu simulated drains to %s (provenance: simulated)\n", drains.size(), terminal_safe(a.out).c_str());
  return exit_code::kOk;
}

}  // namespace

void add_experiment_command(CLI::App& app, int& exit_status) {
  CLI::App* ex = app.add_subcommand("experiment", "Draining-hopper data beside the simulations (docs/experiments.md)");
  ex->require_subcommand(1);

  auto ia = std::make_shared<ImportArgs>();
  CLI::App* imp = ex->add_subcommand("import", "Read droplet exits (CSV, SI units), fit c0 per run, store the series");
  imp->add_option("file", ia->file, "CSV of exits: run,w_m,t_s (or run,w_m,t_s,N)")->required();
  imp->add_option("--dir", ia->dir, "campaign directory (created if missing)")->required();
  imp->add_option("--series", ia->o.series, "series name (default: the file's header, else its name)");
  imp->add_option("--provenance", ia->o.provenance, "measured | simulated (default: the file's header)");
  imp->add_option("--sigma-m", ia->sigma, "mean droplet diameter, metres (overrides the header)");
  imp->add_option("--g-eff", ia->g_eff, "effective gravity, m/s^2 (overrides the header)");
  imp->add_option("--rho-drop", ia->rho_drop, "droplet density, kg/m^3 (with --rho-medium instead of --g-eff)");
  imp->add_option("--rho-medium", ia->rho_medium, "surrounding fluid's density, kg/m^3");
  imp->add_option("--fit-skip", ia->o.fit_skip, "exits left out at each end of a run's fit (default 100)");
  imp->add_option("--block-exits", ia->o.block_exits, "exits per rate block (default 10)");
  imp->add_flag("--replace", ia->o.replace, "replace a series of the same name");
  imp->callback([ia, &exit_status] {
    exit_status = guarded("experiment import", [&] { return import_command(*ia); });
  });

  auto ea = std::make_shared<ExportArgs>();
  CLI::App* exp = ex->add_subcommand("export-drain", "Write simulated drains (job directories) as a data file, labelled simulated");
  exp->add_option("jobs", ea->jobs, "job directories of finished draining runs (reinject = false)")->required();
  exp->add_option("-o,--output", ea->out, "the CSV to write")->required();
  exp->add_option("--sigma-m", ea->sigma, "droplet diameter to convert to, metres")->required();
  exp->add_option("--g-eff", ea->g_eff, "effective gravity to convert to, m/s^2")->required();
  exp->add_option("--series", ea->series, "series name in the file's header");
  exp->add_option("--geometry", ea->geometry, "geometry in the file's header (e.g. 45/45)");
  exp->callback([ea, &exit_status] {
    exit_status = guarded("experiment export-drain", [&] { return export_command(*ea); });
  });
}

}  // namespace beverloo
