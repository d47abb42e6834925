// The coarse-grained velocity along gravity v_g(h) on the centre line, per job of the first
// four series, with its error as a band.
#include "core/text_escape.h"
#include "figure.h"

namespace beverloo::figures {

ReportFigure velocity_profiles(const FigureContext& c) {
  Figure f("velocity_profiles", "Coarse-grained velocity along gravity v_g(h) on the centre line (band: its error)",
           "h / sigma_avg (height above the orifice)", "v_g / (sigma_avg / t0)");
  struct Curve {
    std::string label;
    std::string rows;
  };
  std::vector<Curve> curves;
  db::Statement st = c.db.prepare(
      "SELECT j.w, p.h, p.v_g, p.v_g_err FROM velocity_profiles p JOIN jobs j ON j.key = p.job_key "
      "WHERE p.job_key = ?1 ORDER BY p.h");
  int shown = 0;
  for (const Series& s : c.fits.series) {
    if (s.rate_is_c0()) continue;  // a draining hopper has no steady profile
    if (shown++ >= 4) break;  // the first four series; the data of all are in the database
    for (const std::string& key : s.job_keys) {
      st.bind(1, key);
      double w = 0;
      std::ostringstream rows;
      bool any = false;
      while (st.step()) {
        any = true;
        w = st.get_double(0);
        rows << num(st.get_double(1)) << " " << num(st.get_double(2)) << " " << num(st.get_double(3)) << "\n";
      }
      st.reset();
      if (any) curves.push_back({s.label + ", w = " + num(w), rows.str()});
    }
  }
  const int n = static_cast<int>(curves.size());
  for (int k = 0; k < n; ++k) {
    const int block = f.begin_block(curves[k].label + ": h v_g v_g_err");
    f.data << curves[k].rows;
    const std::string style = series_style(k, n), colour = style.substr(0, style.find(" pt"));
    f.plots.push_back("DATA index " + std::to_string(block) +
                      " using 1:($2-$3):($2+$3) with filledcurves fs transparent solid 0.25 noborder " + colour +
                      " notitle");
    f.plots.push_back("DATA index " + std::to_string(block) + " using 1:2 with lines lw 1.5 " + colour + " title " +
                      gnuplot_string(curves[k].label));
  }
  return finish(f, c.dir, "no velocity profiles in the database");
}

}  // namespace beverloo::figures
