// Diagnostic: do DP polygons roll in a friction-only flow? For neighbouring polygons (centroids
// closer than 1.02 x the sum of their reference radii) compare the tangential relative velocity
// of the centres (what SP friction sees) with that at the contact point (midpoint between
// surfaces along the centre line), which includes rotation (what DP contact friction sees).
// Usage: dp_rolling '<job json>' t_transient t_sample
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include "engine/config.h"
#include "engine/protocol/hopper_run.h"
using namespace beverloo;
int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s '<job json>' t_transient t_sample\n", argv[0]);
    return 2;
  }
  auto c = SimConfig::from_json(nlohmann::json::parse(argv[1]));
  c.resolve_and_validate();
  double t_tr = std::atof(argv[2]), t_s = std::atof(argv[3]);
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  DpSystem& dp = *run.dp();
  // advance through the transient in chunks
  auto advance_to = [&](double t) { while (run.time() < t) run.advance(200); };
  advance_to(t_tr);
  const PolygonSet& P = dp.polygons();
  const int M = P.polygons();
  std::vector<Vec<2>> cen(M), vel(M); std::vector<double> om(M), rad(M);
  double sum_tc = 0, sum_tp = 0, ke_t = 0, ke_r = 0; long npairs = 0, nsamples = 0;
  double next = t_tr;
  while (run.time() < t_tr + t_s) {
    advance_to(next); next += 0.5;
    const auto& v = dp.verts();
    for (int m = 0; m < M; ++m) {
      int a = P.first[m], b = P.first[m + 1], n = b - a;
      Vec<2> x = Vec<2>::Zero(), u = Vec<2>::Zero();
      for (int i = a; i < b; ++i) { x += v.x[i]; u += v.v[i]; }
      x /= n; u /= n;
      double L = 0, I = 0, r2 = 0;
      for (int i = a; i < b; ++i) { Vec<2> r = v.x[i] - x, w = v.v[i] - u; L += r.x() * w.y() - r.y() * w.x(); I += r.squaredNorm(); r2 += r.norm(); }
      cen[m] = x; vel[m] = u; om[m] = L / I; rad[m] = r2 / n;
      ke_t += 0.5 * u.squaredNorm(); ke_r += 0.5 * om[m] * om[m] * I / n;  // per unit vertex mass
    }
    for (int m = 0; m < M; ++m) if (cen[m].y() > 0.5)
      for (int k = m + 1; k < M; ++k) {
        Vec<2> d = cen[k] - cen[m]; double r = d.norm();
        if (cen[k].y() < 0.5 || r > 1.02 * (rad[m] + rad[k]) + 0.05) continue;
        Vec<2> nh = d / r, th(-nh.y(), nh.x());
        double vtc = (vel[k] - vel[m]).dot(th);
        // contact-point velocities: v + omega x r, r = +-rad along the centre line
        double vm = vel[m].dot(th) + om[m] * rad[m], vk = vel[k].dot(th) - om[k] * rad[k];
        sum_tc += vtc * vtc; sum_tp += (vk - vm) * (vk - vm); ++npairs;
      }
    ++nsamples;
  }
  std::printf("model %s mu %g zeta %g: pairs/sample %.1f  <dv_t^2> centres %.4g  contact points %.4g  ratio %.3f  KE_rot/KE_trans %.3f\n",
              c.model.c_str(), c.mu, c.zeta, double(npairs) / nsamples, sum_tc / npairs, sum_tp / npairs, sum_tp / sum_tc, ke_r / ke_t);
}
