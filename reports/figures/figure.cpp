#include "figure.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/atomic_file.h"
#include "core/child_process.h"
#include "core/errors.h"
#include "core/text_escape.h"

namespace beverloo::figures {
namespace fs = std::filesystem;

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string series_style(int k, int n) {
  // Okabe & Ito (2008), the colour-blind-safe qualitative set, black last
  static const char* okabe_ito[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000"};
  // viridis at 0, 1/8, ..., 1 (perceptually uniform, monotone in lightness): interpolated below
  static const double viridis[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},  {44, 113, 142}, {33, 144, 141},
                                       {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  // filled and open shapes alternate, so that neighbours differ in more than colour
  static const int markers[] = {7, 5, 9, 11, 13, 6, 4, 8, 10, 12, 15, 1, 2, 3, 14};
  char colour[8];
  if (n <= 8) {
    std::snprintf(colour, sizeof colour, "%s", okabe_ito[k % 8]);
  } else {
    const double t = 0.9 * k / (n - 1) * 8;  // stop short of the pale yellow end
    const int i = std::min(7, static_cast<int>(t));
    const double f = t - i;
    int rgb[3];
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<int>(std::lround(viridis[i][c] * (1 - f) + viridis[i + 1][c] * f));
    std::snprintf(colour, sizeof colour, "#%02X%02X%02X", rgb[0], rgb[1], rgb[2]);
  }
  return std::string("lc rgb '") + colour + "' pt " + std::to_string(markers[k % 15]);
}

int Figure::begin_block(const std::string& header) {
  if (blocks) data << "\n\n";
  data << "# " << terminal_safe(header) << "\n";  // one comment line, whatever the header holds
  return blocks++;
}

namespace {
/// A figure of a few thousand points renders in well under a second; a gnuplot that takes this
/// long is stuck (a damaged font cache, a terminal waiting for input).
constexpr double kGnuplotTimeLimit_s = 120;

/// Whether gnuplot runs here (asked once per process).
bool gnuplot_available() {
  static const bool yes = run_child({"gnuplot", "--version"}, kGnuplotTimeLimit_s).rc == 0;
  return yes;
}

/// Writes f's data and script and renders them; false (data and script written) if this
/// machine has no gnuplot.
bool render(Figure& f, const fs::path& dir) {
  const std::string dat = f.name + ".dat";
  write_text_atomically((dir / dat).string(), f.data.str());
  std::ostringstream gp;
  // the title is the page's caption (index.html), not repeated inside the figure
  // Every text that is not beverloo's own gnuplot syntax goes in as a single-quoted literal
  // (gnuplot_string): a user's series or run name is data, never a command.
  gp << "# " << terminal_safe(f.title) << "\n# Rendered by beverloo report; edit and run `gnuplot " << f.name
     << ".gp` in this directory.\n"
     << "set xlabel " << gnuplot_string(f.xlabel) << " noenhanced\nset ylabel " << gnuplot_string(f.ylabel) << " noenhanced\n"
     << "set key outside below left Left reverse maxrows 8 font ',9' noenhanced\nset grid\nset pointsize 1.1\n"
     << f.extra;
  auto with_data = [&](std::string text) {
    for (std::size_t pos; (pos = text.find("DATA")) != std::string::npos;) text.replace(pos, 4, "'" + dat + "'");
    return text;
  };
  std::string plot = f.body.empty() ? "plot " : with_data(f.body);
  for (std::size_t k = 0; f.body.empty() && k < f.plots.size(); ++k) plot += (k ? ", \\\n     " : "") + with_data(f.plots[k]);
  // the commands once per terminal (replot cannot repeat a multiplot)
  const std::string size = std::to_string(f.width) + "," + std::to_string(f.height);
  gp << "set terminal svg size " << size << " dynamic background rgb 'white'\nset output '" << f.name << ".svg'\n" << plot
     << "\nset terminal pngcairo size " << size << "\nset output '" << f.name << ".png'\n" << plot << "\nunset output\n";
  write_text_atomically((dir / (f.name + ".gp")).string(), gp.str());
  if (!gnuplot_available()) return false;
  // no shell: the report directory's path is an argument, never part of a command line
  const ChildResult r = run_child({"gnuplot", f.name + ".gp"}, kGnuplotTimeLimit_s, dir.string());
  if (r.rc != 0 || !fs::exists(dir / (f.name + ".svg")) || !fs::exists(dir / (f.name + ".png"))) {
    const fs::path log = dir / (f.name + ".log");
    write_text_atomically(log.string(), r.text());
    throw IoError("gnuplot failed on " + (dir / (f.name + ".gp")).string() +
                  (r.rc == 127 ? " (is gnuplot installed and on PATH?)" : "") + " (see " + log.string() + ")");
  }
  fs::remove(dir / (f.name + ".log"));
  return true;
}
}  // namespace

ReportFigure finish(Figure& f, const fs::path& dir, const std::string& needs) {
  ReportFigure r{f.name, f.title, false, ""};
  if (f.blocks == 0) {
    r.why_not = needs;
  } else if (render(f, dir)) {
    r.made = true;
  } else {
    r.why_not = "gnuplot is not installed here (apt-get install gnuplot-nox); its data and script are written: run `gnuplot " +
                f.name + ".gp` in this directory";
  }
  return r;
}

const std::vector<FigureMaker>& report_figures() {
  static const std::vector<FigureMaker> list = {q_vs_w,          loglog_collapse,   beta_vs_lambda, lambda_c_vs_theta,
                                                k_vs_Esp,        k_vs_Kb,           k_heatmap_Kl_Kb, prefactor_vs_N,
                                                velocity_profiles, velocity_regimes, drain_q_vs_w,   drain_collapse,
                                                drain_curves,    clog_survival,     q_prime_vs_w};
  return list;
}

}  // namespace beverloo::figures
