// What a reinjection rule does to the energy of a flow (issue 32 item 6): runs an SP job and
// prints, every `every_t0`, the kinetic energy per particle, the fastest particle (speed,
// height) and the highest particle; and what the reinjections did to the kinetic energy: per
// reinjected particle, its kinetic energy just before it was taken out and just after it was
// placed (mean, and the largest placed).
// Usage: reinjection_energy '<job json>' t_end every_t0
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/config.h"
#include "engine/protocol/hopper_run.h"

using namespace beverloo;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s '<job json>' t_end every_t0\n", argv[0]);
    return 2;
  }
  SimConfig c = SimConfig::from_json(nlohmann::json::parse(argv[1]));
  const double t_end = std::atof(argv[2]), every = std::atof(argv[3]);
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const double dt = run.time_step().dt;
  const auto chunk = std::max<std::int64_t>(1, std::llround(every / dt));
  std::printf("#     t   K/N      v_max   y(v_max)  vy(v_max)  y_top   reinjections  K_out  K_in  K_in_max  vy_in>1\n");
  std::int64_t last_reinj = 0;
  std::vector<double> y_before, k_before;
  try {
    while (run.time() < t_end) {
      double k_out = 0, k_in = 0, k_in_max = 0;
      int placed = 0, upward = 0;
      for (std::int64_t step = 0; step < chunk; ++step) {
        const ParticleState<2>& s = run.state();
        y_before.resize(s.size());
        k_before.resize(s.size());
        for (int i = 0; i < s.size(); ++i) {  // by id: the SP path sorts its particles at list builds
          y_before[s.id[i]] = s.x[i][1];
          k_before[s.id[i]] = 0.5 * s.mass(i) * s.v[i].squaredNorm();
        }
        run.advance(1);
        for (int i = 0; i < s.size(); ++i) {
          if (s.x[i][1] < y_before[s.id[i]] + 1.0) continue;  // not moved up by a placement
          const double k = 0.5 * s.mass(i) * s.v[i].squaredNorm();
          ++placed;
          k_out += k_before[s.id[i]];
          k_in += k;
          k_in_max = std::max(k_in_max, k);
          upward += s.v[i][1] > 1.0;
        }
      }
      const ParticleState<2>& s = run.state();
      double k = 0, vmax = 0, ytop = -1e300;
      int fastest = 0;
      for (int i = 0; i < s.size(); ++i) {
        const double v2 = s.v[i].squaredNorm();
        k += 0.5 * s.mass(i) * v2;
        if (v2 > vmax * vmax) {
          vmax = std::sqrt(v2);
          fastest = i;
        }
        ytop = std::max(ytop, s.x[i][1]);
      }
      const std::int64_t r = run.record().reinjections;
      const double per = placed ? 1.0 / placed : 0.0;
      std::printf("%7.2f %8.4f %8.3f %8.2f %9.3f %8.2f %6lld %8.3f %6.3f %8.3f %4d\n", run.time(), k / s.size(), vmax,
                  s.x[fastest][1], s.v[fastest][1], ytop, static_cast<long long>(r - last_reinj), k_out * per, k_in * per,
                  k_in_max, upward);
      last_reinj = r;
    }
  } catch (const std::exception& e) {
    std::printf("# stopped: %s\n", e.what());
  }
}
