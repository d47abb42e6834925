// `beverloo fit DIR` and `beverloo report DIR [-o OUT]`.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "commands.h"
#include "guarded.h"
#include "core/errors.h"
#include "core/failures.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "reports/campaign_fits.h"
#include "reports/next_width.h"
#include "reports/report.h"
#include "core/text_escape.h"

namespace beverloo {
namespace fs = std::filesystem;

namespace {
/// A new private directory under the system's temporary directory (mkdtemp: no race).
std::string make_scratch_dir(const std::string& prefix) {
  std::string path = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (::mkdtemp(path.data()) == nullptr) throw IoError("cannot create a temporary directory like " + path);
  return path;
}
}  // namespace

int report_campaign(const std::string& dir, const std::string& out, const std::string& campaign) {
  return guarded("report", [&] {
    const CampaignScope scope = CampaignScope::parse(campaign, "--campaign");
    const auto figures = write_report(dir, out, scope);
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

namespace {
/// `fit --next`: per fitted series, the next width by reports/next_width.h.
void print_next_widths(const CampaignFits& fits, const DesignTargets& targets, const std::vector<double>& range,
                       double step) {
  std::printf("\nNext run per series (A-optimal for k and beta per CPU, candidates every %g; reports/next_width.h)\n\n", step);
  std::printf("| series | k now | beta now | next w | k_err after | beta_err after | relative cost |\n|---|---|---|---|---|---|---|\n");
  for (const Series& s : fits.series) {
    const std::string label = markdown_cell(s.label);
    if (!s.fit || s.rate_is_c0()) {
      std::printf("| %s | no fit | | | | | |\n", label.c_str());
      continue;
    }
    std::vector<double> w, Q, err;
    s.flowing_columns(w, Q, err);
    const double lo = range.size() == 2 ? range[0] : w.front() - 2, hi = range.size() == 2 ? range[1] : w.back();
    try {
      const DesignAdvice a = next_width(*s.fit, w, Q, err, lo, hi, step, targets);
      std::printf("| %s | %.3g +- %.2g | %.3g +- %.2g | ", label.c_str(), s.fit->k, a.k_err_now, s.fit->beta, a.beta_err_now);
      if (a.targets_met)
        std::printf("targets met | | | |\n");
      else
        std::printf("%.4g | %.2g | %.2g | %.2f |\n", a.next->w, a.next->k_err_after, a.next->beta_err_after, a.next->relative_cost);
    } catch (const FitError& e) {
      std::printf("| %s | %s | | | | | |\n", label.c_str(), markdown_cell(e.what()).c_str());
    }
  }
}
}  // namespace

void add_report_commands(CLI::App& app, int& exit_status) {
  auto dir = std::make_shared<std::string>();
  CLI::App* fit = app.add_subcommand("fit", "Fit Q = C (w - k)^beta per series and beta(lambda) per group");
  fit->add_option("DIR", *dir, "campaign directory")->required();
  auto authors_way = std::make_shared<bool>(false);
  fit->add_flag("--authors-way", *authors_way,
                "also print every exponent fitted as the paper's authors fitted theirs (bounded, unweighted, 2 < w < 19) "
                "and the crossover with free plateaus, beside the default fits (docs/paper.md)");
  auto next = std::make_shared<bool>(false);
  fit->add_flag("--next", *next,
                "also print, per series, the width whose next run would shrink the errors of k and beta most per "
                "CPU (A-optimal design; docs/cli.md)");
  auto k_err = std::make_shared<double>(NAN), beta_err = std::make_shared<double>(NAN), w_step = std::make_shared<double>(0.25);
  auto w_range = std::make_shared<std::vector<double>>();
  fit->add_option("--k-err", *k_err, "--next: the standard error of k wanted (a target)")->check(CLI::PositiveNumber);
  fit->add_option("--beta-err", *beta_err, "--next: the standard error of beta wanted (a target)")->check(CLI::PositiveNumber);
  fit->add_option("--w-range", *w_range, "--next: the widths allowed, LO HI (default: 2 below the series' smallest to its largest)")
      ->expected(2);
  fit->add_option("--w-step", *w_step, "--next: the grid of candidate widths (default 0.25)")->check(CLI::PositiveNumber);
  auto flow_rate = std::make_shared<std::string>("Q");
  fit->add_option("--flow-rate", *flow_rate,
                  "Q (default) | Q_prime: fit Appendix B's Q' = Q a_eff / a_avg instead (printed, not stored)")
      ->check(CLI::IsMember({"Q", "Q_prime"}));
  auto fit_campaigns = std::make_shared<std::string>("latest");
  fit->add_option("--campaign", *fit_campaigns,
                  "latest (default) | all | ID: which campaigns of DIR to fit (a directory holds one per sweep run "
                  "in it; all: every job of every campaign, each once)");
  fit->callback([dir, authors_way, next, k_err, beta_err, w_range, w_step, flow_rate, fit_campaigns, &exit_status] {
    exit_status = guarded("fit", [&] {
      const CampaignScope scope = CampaignScope::parse(*fit_campaigns, "--campaign");
      // While a coordinator runs the campaign (one writer at a time), the results stored so far
      // are fitted read-only: printed, not stored, the campaign's files untouched. A week-long
      // campaign's user wants its fits before its end.
      std::optional<CampaignWriter> writer;
      std::optional<CampaignReader> reader;
      try {
        writer.emplace(*dir, CampaignWriter::Open::MustExist);
      } catch (const CampaignBusy&) {
        reader.emplace(*dir);
        std::printf("fit: a coordinator is running this campaign: the results stored so far, fitted read-only "
                    "(printed, not stored; `beverloo fit` after it stops stores them)\n\n");
      }
      db::Database& db = writer ? writer->db() : reader->db();
      scope.check_exists(db, "--campaign");
      if (*fit_campaigns != "latest") std::printf("fit: %s of %s\n\n", scope.describe(db).c_str(), terminal_safe(*dir).c_str());
      // Q' (Appendix B): fitted and printed, never stored: the stored fits and the report are Q's
      const bool q_prime = *flow_rate == "Q_prime";
      if (q_prime)
        std::printf("fit: the flow rate Q' = Q a_eff / a_avg (Appendix B; a_eff = 1/rho_n near the orifice), printed, "
                    "not stored\n\n");
      const CampaignFits fits = fit_campaign(db, q_prime ? FlowRate::QPrime : FlowRate::Q, scope);
      if (fits.series.empty()) {
        std::printf("fit: nothing to fit in %s: no job has a stored result and no series was imported "
                    "(`beverloo campaign status --dir %s` shows where the jobs are)\n",
                    terminal_safe(*dir).c_str(), terminal_safe(*dir).c_str());
        return exit_code::kOk;
      }
      const bool store = writer && !q_prime;
      if (store) store_fits(db, fits);
      // not stored: the tables go to a directory of our own, removed when printed
      const std::string out = store ? campaign_dir::report_path(*dir) : make_scratch_dir("beverloo-fit");
      struct RemoveScratch {
        std::string dir;
        ~RemoveScratch() {
          std::error_code ec;
          if (!dir.empty()) fs::remove_all(dir, ec);
        }
      } scratch{store ? std::string() : out};
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
      if (*next) {
        DesignTargets targets;
        if (std::isfinite(*k_err)) targets.k_err = *k_err;
        if (std::isfinite(*beta_err)) targets.beta_err = *beta_err;
        print_next_widths(fits, targets, *w_range, *w_step);
      }
      for (const Series& s : fits.series) {
        if (s.left_out > 0)
          std::printf("\n%s: %d replica(s) with a flow rate but no usable error (Q_err not > 0) left out of the fit\n",
                      terminal_safe(s.label).c_str(), s.left_out);
        if (s.continued > 0)
          std::printf("\n%s: %d run(s) continued by a longer run of the same trajectory (run.min_time): the longer "
                      "run is the point\n", terminal_safe(s.label).c_str(), s.continued);
      }
      if (!store) return exit_code::kOk;
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
  auto report_campaigns = std::make_shared<std::string>("latest");
  report->add_option("--campaign", *report_campaigns,
                     "latest (default) | all | ID: which campaigns of DIR the report covers (all: every job of every "
                     "campaign, each once)");
  report->callback([rdir, out, report_campaigns, &exit_status] {
    exit_status = report_campaign(*rdir, out->empty() ? campaign_dir::report_path(*rdir) : *out, *report_campaigns);
  });
}

}  // namespace beverloo
