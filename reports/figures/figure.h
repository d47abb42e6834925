#pragma once
/// \file figure.h
/// \brief What every report figure shares: a Figure is data blocks (gnuplot "index") and plot
/// clauses, rendered by gnuplot to SVG and PNG beside its .dat and .gp (so that a user can
/// restyle it); a FigureMaker turns a campaign's fits and database into one Figure or says
/// what data it lacks. The report's list of makers is figure_list.cpp.
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "orchestrator/db/database.h"
#include "reports/campaign_fits.h"
#include "reports/report.h"

namespace beverloo::figures {

/// Inputs of every figure.
struct FigureContext {
  const CampaignFits& fits;
  db::Database& db;
  std::filesystem::path dir;  ///< the report directory
  CampaignScope scope = CampaignScope::latest();  ///< the campaigns the report covers
};

using FigureMaker = ReportFigure (*)(const FigureContext&);

/// Text of a number for data files (full precision: the figure's data stays the data).
std::string num(double v);

/// The style of the k-th of n series in one figure: its own colour (Okabe-Ito for up to 8,
/// else evenly spaced along viridis, both readable by colour-blind readers and in grey) and its
/// own marker; returned as gnuplot "lc rgb '#..' pt N".
std::string series_style(int k, int n);

/// gnuplot line style of a value the paper states (its plateaus, its lambda_c): thick, long
/// dashes and grey, so that it stands out from `set grid`'s thin dotted lines even where it lies
/// on one (beta = 1.5 and 0.5 are grid lines of most beta axes).
inline constexpr const char* kPaperLineStyle = "lw 2.5 dt (12,6) lc rgb 'gray55'";

struct Figure {
  Figure(std::string n, std::string t, std::string x, std::string y, std::string e = "")
      : name(std::move(n)), title(std::move(t)), xlabel(std::move(x)), ylabel(std::move(y)), extra(std::move(e)) {}
  std::string name, title, xlabel, ylabel, extra;  ///< extra: more "set" lines (log scales, ...)
  std::ostringstream data;
  std::vector<std::string> plots;  ///< plot clauses; "DATA" stands for the data file
  std::string body;                ///< instead of plots: whole gnuplot commands (multiplot), "DATA" as above
  int width = 900, height = 720;  ///< pixels (SVG and PNG); a multiplot of three panels is wider
  int blocks = 0;
  /// Starts a data block; returns its gnuplot index.
  int begin_block(const std::string& header);
};

/// Renders f if it has data blocks; otherwise records what data it needs. Throws IoError if
/// gnuplot fails.
ReportFigure finish(Figure& f, const std::filesystem::path& dir, const std::string& needs);

/// The report's figures, in the order index.html shows them.
const std::vector<FigureMaker>& report_figures();

ReportFigure q_vs_w(const FigureContext& c);
ReportFigure q_prime_vs_w(const FigureContext& c);
ReportFigure loglog_collapse(const FigureContext& c);
ReportFigure beta_vs_lambda(const FigureContext& c);

/// The y range of beta_vs_lambda: the paper's plateaus widened to every exponent measured to
/// 0.5 or better (with its error bar), 0.2 either side; `beyond` counts the exponents left
/// outside. None without a beta(lambda) group.
struct BetaFrame {
  double lo, hi;
  int beyond;
};
std::optional<BetaFrame> beta_vs_lambda_frame(const CampaignFits& fits);
ReportFigure lambda_c_vs_theta(const FigureContext& c);
ReportFigure k_vs_Esp(const FigureContext& c);
ReportFigure k_vs_Kb(const FigureContext& c);
ReportFigure k_heatmap_Kl_Kb(const FigureContext& c);
ReportFigure prefactor_vs_N(const FigureContext& c);
ReportFigure velocity_profiles(const FigureContext& c);
ReportFigure velocity_regimes(const FigureContext& c);
ReportFigure drain_q_vs_w(const FigureContext& c);
ReportFigure drain_collapse(const FigureContext& c);
ReportFigure drain_curves(const FigureContext& c);
ReportFigure clog_survival(const FigureContext& c);

/// The data and plot clauses of Q(w) with fitted curves, and of the log-log collapse, for a
/// list of series (shared by the continuous-flow and the draining-hopper figures).
void plot_q_vs_w(Figure& f, const std::vector<const Series*>& list);
void plot_collapse(Figure& f, const std::vector<const Series*>& list);

}  // namespace beverloo::figures
