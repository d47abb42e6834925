// Imported draining-hopper series (schema/0006_experiments.sql) as fit series: the runs' Q =
// c0 t0 against w / sigma_avg, runs at one width pooled by inverse-variance weights, fitted with
// the same Beverloo fit as the simulations.
#include <cmath>
#include <map>
#include <sstream>

#include "campaign_fits.h"
#include "core/digest.h"

namespace beverloo {

void add_experiment_series(db::Database& db, CampaignFits& out) {
  if (!db.has_table("experiment_series")) return;  // a store from before the experiments (readers do not migrate)
  db::Statement series = db.prepare("SELECT id, name, provenance, geometry FROM experiment_series ORDER BY id");
  db::Statement runs = db.prepare(
      "SELECT w, Q, Q_err FROM experiment_runs WHERE series_id = ?1 ORDER BY w, run");
  while (series.step()) {
    Series s;
    s.experiment_id = series.get_int(0);
    s.model = "experiment";
    s.provenance = series.get_text(2);
    s.key = sha256_hex("experiment\n" + series.get_text(1));
    const std::string geometry = series.get_text(3);
    std::ostringstream label;
    label << series.get_text(1) << (s.provenance == "measured" ? " (measured" : " (simulated by beverloo, not measured");
    if (!geometry.empty()) label << ", " << geometry;
    label << ")";
    s.label = label.str();
    std::map<double, std::pair<double, double>> pooled;  // w -> (sum 1/err^2, sum Q/err^2)
    std::map<double, int> replicas;
    runs.bind(1, s.experiment_id);
    while (runs.step()) {
      const double w = runs.get_double(0);
      ++replicas[w];
      if (runs.is_null(1) || runs.is_null(2)) continue;  // a run without a fit
      const double Q = runs.get_double(1), err = runs.get_double(2);
      if (!(Q > 0) || !(err > 0)) continue;
      pooled[w].first += 1 / (err * err);
      pooled[w].second += Q / (err * err);
    }
    std::vector<double> w, Q, e;
    for (const auto& [width, count] : replicas) {
      SeriesPoint p;
      p.w = width;
      p.replicas = count;
      if (pooled.count(width)) {
        p.Q = pooled[width].second / pooled[width].first;
        p.Q_err = 1 / std::sqrt(pooled[width].first);
        w.push_back(p.w);
        Q.push_back(p.Q);
        e.push_back(p.Q_err);
      }
      s.points.push_back(p);
    }
    try {
      s.fit = fit_beverloo(w, Q, e);
    } catch (const FitError& err) {
      s.message = err.what();
    }
    out.series.push_back(std::move(s));
  }
}

}  // namespace beverloo
