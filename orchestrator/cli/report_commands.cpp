// `beverloo fit DIR` and `beverloo report DIR [-o OUT]`.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "commands.h"
#include "guarded.h"
#include "core/errors.h"
#include "core/failures.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "reports/campaign_fits.h"
#include "reports/report.h"
#include "core/text_escape.h"

namespace beverloo {
namespace fs = std::filesystem;

int report_campaign(const std::string& dir, const std::string& out) {
  return guarded("report", [&] {
    const auto figures = write_report(dir, out);
    int made = 0;
    for (const auto& f : figures) made += f.made;
    std::printf("report: %s/index.html (%d of %zu figures; tables beverloo_fits and crossover_fits)\n", terminal_safe(out).c_str(), made,
                figures.size());
    // the tables and index.html are made without gnuplot; its figures are not: said, not failed
    for (const auto& f : figures)
      if (!f.made && f.why_not.rfind("gnuplot is not installed", 0) == 0) {
        std::fprintf(stderr, "beverloo report: gnuplot is not installed here: the figures' data and scripts are written, "
                             "not their images (apt-get install gnuplot-nox, then `beverloo report` again)\n");
        break;
      }
    return exit_code::kOk;
  });
}

void add_report_commands(CLI::App& app, int& exit_status) {
  auto dir = std::make_shared<std::string>();
  CLI::App* fit = app.add_subcommand("fit", "Fit Q = C (w - k)^beta per series and beta(lambda) per group");
  fit->add_option("DIR", *dir, "campaign directory")->required();
  auto authors_way = std::make_shared<bool>(false);
  fit->add_flag("--authors-way", *authors_way,
                "also print every exponent fitted as the paper's authors fitted theirs (bounded, unweighted, 2 < w < 19) "
                "and the crossover with free plateaus, beside the default fits (docs/paper.md)");
  fit->callback([dir, authors_way, &exit_status] {
    exit_status = guarded("fit", [&] {
      CampaignWriter writer(*dir, CampaignWriter::Open::MustExist);
      db::Database& db = writer.db();
      const CampaignFits fits = fit_campaign(db);
      if (fits.series.empty()) {
        std::printf("fit: nothing to fit in %s: no job has a stored result and no series was imported "
                    "(`beverloo campaign status --dir %s` shows where the jobs are)\n",
                    terminal_safe(*dir).c_str(), terminal_safe(*dir).c_str());
        return exit_code::kOk;
      }
      store_fits(db, fits);
      const std::string out = campaign_dir::report_path(*dir);
      write_fit_tables(fits, out);
      std::ifstream md(fs::path(out) / "beverloo_fits.md"), xmd(fs::path(out) / "crossover_fits.md");
      std::cout << md.rdbuf() << "\n" << xmd.rdbuf();
      bool clogs = false;
      for (const Series& s : fits.series) clogs = clogs || !s.clog_points.empty();
      if (clogs) {
        std::ifstream cmd(fs::path(out) / "clog_statistics.md");
        std::cout << "\nClogging: the time to a clog over the replicas (Kaplan-Meier; runs that ended flowing censored)\n\n"
                  << cmd.rdbuf();
      }
      if (*authors_way) {
        std::ifstream bmd(fs::path(out) / "beverloo_fits_both_ways.md"), fmd(fs::path(out) / "crossover_fits_both_ways.md");
        std::cout << "\nBoth ways: beverloo's free fit (the default) beside the authors' bounded one\n\n" << bmd.rdbuf()
                  << "\n" << fmd.rdbuf();
      }
      for (const Series& s : fits.series)
        if (s.left_out > 0)
          std::printf("\n%s: %d replica(s) with a flow rate but no usable error (Q_err not > 0) left out of the fit\n",
                      terminal_safe(s.label).c_str(), s.left_out);
      std::printf("\nfits stored in %s/campaign.sqlite (views beverloo_fits, crossover_fits, beverloo_fits_both_ways, crossover_fits_both_ways, clog_statistics) and %s/*.csv, *.md\n",
                  terminal_safe(*dir).c_str(), terminal_safe(out).c_str());
      return exit_code::kOk;
    });
  });
  auto rdir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* report = app.add_subcommand("report", "Fits, tables and gnuplot figures (SVG, PNG) with index.html");
  report->add_option("DIR", *rdir, "campaign directory")->required();
  report->add_option("-o,--output", *out, "output directory (default: DIR/report)");
  report->callback([rdir, out, &exit_status] {
    exit_status = report_campaign(*rdir, out->empty() ? campaign_dir::report_path(*rdir) : *out);
  });
}

}  // namespace beverloo
