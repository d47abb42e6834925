#include "survival.h"

#include <algorithm>
#include <cmath>

namespace beverloo {

KaplanMeier kaplan_meier(std::vector<SurvivalObservation> obs) {
  KaplanMeier km;
  km.runs = static_cast<int>(obs.size());
  // by time; at equal times clogs first, so a run censored then is still at risk at the clog
  std::sort(obs.begin(), obs.end(), [](const SurvivalObservation& a, const SurvivalObservation& b) {
    return a.time != b.time ? a.time < b.time : (a.clogged && !b.clogged);
  });
  double S = 1, greenwood = 0;
  int at_risk = km.runs;
  for (std::size_t i = 0; i < obs.size();) {
    const double t = obs[i].time;
    int clogs = 0, leaving = 0;
    for (; i < obs.size() && obs[i].time == t; ++i, ++leaving) clogs += obs[i].clogged;
    if (clogs > 0) {
      S *= 1.0 - static_cast<double>(clogs) / at_risk;
      // Greenwood: Var S = S^2 sum d / (n (n - d)); undefined (S = 0) when everyone at risk clogs
      if (at_risk > clogs) greenwood += static_cast<double>(clogs) / (static_cast<double>(at_risk) * (at_risk - clogs));
      km.time.push_back(t);
      km.survival.push_back(S);
      km.survival_err.push_back(S * std::sqrt(greenwood));
      km.clogs += clogs;
    }
    at_risk -= leaving;
  }
  return km;
}

double KaplanMeier::at(double t) const {
  double S = 1;
  for (std::size_t i = 0; i < time.size() && time[i] <= t; ++i) S = survival[i];
  return S;
}

double KaplanMeier::err_at(double t) const {
  double e = 0;
  for (std::size_t i = 0; i < time.size() && time[i] <= t; ++i) e = survival_err[i];
  return e;
}

double KaplanMeier::median() const {
  for (std::size_t i = 0; i < time.size(); ++i)
    if (survival[i] <= 0.5) return time[i];
  return NAN;
}

}  // namespace beverloo
