// Contact structure in a flowing pile: SP contacts per particle (r < sigma_mn) against DP
// polygon contacts (at least one vertex within delta_mn of an edge of the other polygon, either
// way), vertex contacts per polygon contact, and geometric neighbours (centroids closer than
// 1.05 sigma_mn) for both. Only bodies above the floor (y > 0.5) count.
// Usage: dp_contact_structure '<job json>' t_transient t_sample
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
  const double t_tr = std::atof(argv[2]), t_s = std::atof(argv[3]);
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  auto advance_to = [&](double t) { while (run.time() < t) run.advance(100); };
  advance_to(t_tr);
  const double sig[2] = {1.0 / 1.2, 1.4 / 1.2};  // sigma_s, sigma_l with sigma_avg = 1
  long bodies = 0, geo = 0, touching = 0, vertex_contacts = 0;
  for (double t = t_tr; t < t_tr + t_s; t += 0.25) {
    advance_to(t);
    auto& b = run.state();
    if (run.dp()) run.dp()->sync_bodies(b);
    const int n = b.size();
    for (int m = 0; m < n; ++m) {
      if (b.x[m][1] < 0.5) continue;
      ++bodies;
      for (int k = 0; k < n; ++k) {
        if (k == m) continue;
        const double smn = 0.5 * (sig[b.species[m]] + sig[b.species[k]]);
        const double r = (b.x[k] - b.x[m]).norm();
        if (r < 1.05 * smn) ++geo;
        if (!run.dp()) { if (r < smn) ++touching; continue; }
        if (r > 1.5 * smn) continue;
        const auto& P = run.dp()->polygons();
        const auto& v = run.dp()->verts();
        const auto& delta = run.dp()->shape().delta;
        int here = 0;
        for (int pair = 0; pair < 2; ++pair) {
          const int e_of = pair ? k : m, v_of = pair ? m : k;
          for (int a = P.first[e_of]; a < P.first[e_of + 1]; ++a)
            for (int j = P.first[v_of]; j < P.first[v_of + 1]; ++j) {
              const Vec<2> e = v.x[P.next[a]] - v.x[a], q = v.x[j] - v.x[a];
              double t = q.dot(e) / e.squaredNorm();
              t = t < 0 ? 0 : t > 1 ? 1 : t;
              const double dmn = 0.5 * (delta[v.species[a]] + delta[v.species[j]]);
              if ((q - t * e).norm() < dmn) ++here;
            }
        }
        if (here) { ++touching; vertex_contacts += here; }
      }
    }
  }
  std::printf("%s mu %g zeta %g: geometric neighbours %.2f, touching %.2f per body", c.model.c_str(), c.mu, c.zeta,
              double(geo) / bodies, double(touching) / bodies);
  if (run.dp()) std::printf(", vertex contacts per touching pair %.2f", double(vertex_contacts) / touching);
  std::printf("\n");
}
