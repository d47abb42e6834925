#include "crossover_groups.h"

#include <cmath>
#include <set>

#include "core/digest.h"
#include "engine/parameters.h"
#include "series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;
std::string fmt(double v, int digits = 4) { return table_number(v, digits); }

/// Sorts a crossover group's finite-lambda series and fits the sigmoid to their beta.
void fit_group(Crossover& g) {
  std::sort(g.finite.begin(), g.finite.end(), [](const Series* a, const Series* b) { return a->lambda < b->lambda; });
  std::vector<double> l, b, e;
  for (const Series* s : g.finite) {
    l.push_back(s->lambda);
    b.push_back(s->fit->beta);
    e.push_back(s->fit->beta_err);
  }
  try {
    g.fit = fit_crossover(g.dimension, l, b, e);
  } catch (const FitError& err) {
    g.message = err.what();
  }
  try {
    g.fit_free = fit_crossover_free_plateaus(l, b, e);
  } catch (const FitError& err) {
    g.message_free = err.what();
  }
}
}  // namespace

std::vector<Crossover> crossover_groups(const std::vector<Series>& series, const std::map<std::string, json>& base_job_of) {
  std::vector<Crossover> out;
  // crossover groups: series sharing everything but zeta/mu, with the same drag for finite lambda
  std::map<std::string, Crossover> groups;
  for (const Series& s : series) {
    if (!(s.zeta > 0) || s.drag_rate > 0 || s.drain) continue;  // lambda = 0 joins below as a limit
    std::string gkey = s.base_key + "|zeta=" + fmt(s.zeta, 12);
    if (s.mu_n) gkey += "|mu_n=" + fmt(*s.mu_n, 12);  // (absent for the text's model: keys as before)
    if (s.mu_t) gkey += "|mu_t=" + fmt(*s.mu_t, 12);
    Crossover& g = groups[gkey];
    g.key = sha256_hex(gkey);
    g.angle_family = sha256_hex(s.angle_free_key + gkey.substr(gkey.find('|')));
    g.dimension = s.dimension;
    g.label = std::to_string(s.dimension) + "D " + s.stiffness + " zeta=" + fmt(s.zeta, 3) + " N=" + std::to_string(s.N);
    if (std::isinf(s.lambda))
      g.limit_inf = &s;
    else if (s.fit)
      g.finite.push_back(&s);
    else
      g.unfitted_lambda.push_back(s.lambda);
  }
  for (auto& [gkey, g] : groups) {
    const std::string zeta_part = gkey.substr(gkey.find("|zeta=") + 6);
    const double scale = derived::axis_scale_of_zeta(std::stod(zeta_part.substr(0, zeta_part.find('|'))));
    for (const Series& s : series)  // lambda = 0 at the same dissipation scale
      if (s.zeta == 0 && s.base_key == gkey.substr(0, gkey.find('|')) &&
          std::fabs(derived::axis_scale_of_friction_limit(s.mu) - scale) <= 1e-9 * scale)
        g.limit0 = &s;
    fit_group(g);
    out.push_back(g);
  }
  // The authors' lambda axis (docs/authors-model.md): drag as a rate times the mass, and
  // lambda = drag_rate M(sigma_avg) / mu_t. Their Fig. 4 varies it along two branches, the drag
  // at a fixed friction and then the friction at a fixed drag (Matlab-process oop/paper.m, bVec
  // and vVec), and plots both as one beta(lambda): so a group is every rate-drag series with
  // friction sharing everything else (the form of the friction, mu_n, included). Its limits:
  // lambda = 0, the friction of its lowest-lambda series without drag; lambda = inf, the drag of
  // its highest-lambda series without friction (else any rate-drag series without friction).
  std::map<std::string, Crossover> by_rate_drag;
  for (const Series& s : series) {
    if (!(s.drag_rate > 0) || s.zeta != 0 || !(s.mu > 0) || s.drain) continue;
    const std::string gkey = s.base_key + "|rate_drag|mu_n=" + (s.mu_n ? fmt(*s.mu_n, 12) : "mu");
    Crossover& g = by_rate_drag[gkey];
    g.key = sha256_hex(gkey);
    g.angle_family = sha256_hex(s.angle_free_key + gkey.substr(gkey.find('|')));
    g.dimension = s.dimension;
    if (s.fit)
      g.finite.push_back(&s);
    else
      g.unfitted_lambda.push_back(s.lambda);
  }
  for (auto& [gkey, g] : by_rate_drag) {
    const std::string base = gkey.substr(0, gkey.find('|'));
    const Series* lowest = nullptr;
    const Series* highest = nullptr;
    for (const Series* s : g.finite) {
      if (!lowest || s->lambda < lowest->lambda) lowest = s;
      if (!highest || s->lambda > highest->lambda) highest = s;
    }
    std::set<double> frictions, drags;
    for (const Series* s : g.finite) {
      frictions.insert(s->mu);
      drags.insert(s->drag_rate);
    }
    const Series* any_inf = nullptr;
    for (const Series& s : series) {
      if (s.base_key != base || s.drain) continue;
      if (lowest && s.zeta == 0 && s.drag_rate == 0 && s.mu == lowest->mu && s.mu_n == lowest->mu_n &&
          s.mu_t == lowest->mu_t)
        g.limit0 = &s;
      if (s.mu == 0 && s.zeta == 0 && s.drag_rate > 0) {
        if (highest && s.drag_rate == highest->drag_rate) g.limit_inf = &s;
        if (!any_inf) any_inf = &s;
      }
    }
    if (!g.limit_inf) g.limit_inf = any_inf;
    const Series* any = lowest ? lowest : g.limit0;
    g.label = std::to_string(any ? any->dimension : g.dimension) + "D " + (any ? any->stiffness : std::string()) +
              (frictions.size() == 1   ? " mu=" + fmt(*frictions.begin(), 4) + " (drag rate)"
               : drags.size() == 1     ? " drag_rate=" + fmt(*drags.begin(), 4) + " (mu varied)"
                                       : std::string(" (drag rate and mu varied)")) +
              (any ? " N=" + std::to_string(any->N) : std::string());
    fit_group(g);
    out.push_back(g);
  }
  // groups that differ in something other than their label's fields say so, as series do
  std::vector<std::string> labels;
  std::vector<json> bases;
  for (const Crossover& g : out) {
    const Series* any = !g.finite.empty() ? g.finite.front() : g.limit0 ? g.limit0 : g.limit_inf;
    labels.push_back(g.label);
    bases.push_back(any ? base_job_of.at(any->key) : json::object());
  }
  disambiguate_labels(labels, bases);
  for (std::size_t i = 0; i < labels.size(); ++i) out[i].label = labels[i];
  return out;
}

std::map<std::string, std::map<double, const Crossover*>> angle_families(const std::vector<Crossover>& crossovers,
                                                                         bool fitted_only) {
  std::map<std::string, std::map<double, const Crossover*>> families;
  for (const Crossover& g : crossovers) {
    if (g.finite.empty() || (fitted_only && !g.fit && !g.fit_free)) continue;
    const Series& s = *g.finite.front();
    if (s.theta_left == s.theta_right) families[g.angle_family].emplace(s.theta_left, &g);
  }
  return families;
}

}  // namespace beverloo
