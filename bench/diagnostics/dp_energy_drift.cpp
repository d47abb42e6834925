// The time step's margin for DP, measured: a DP pile settled under gravity with the job's drag
// in a closed hopper, then without any dissipation and with random vertex velocities, run
// conservatively at dt_auto times each given factor. Printed per factor: the largest |E(t) -
// E(0)| over the run relative to the initial kinetic energy, and at the end. Velocity Verlet's
// error should scale as dt^2 until the step stops resolving the stiffest term.
// Usage: dp_energy_drift '<job json>' settle_t0 run_t0 speed factor...
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "engine/config.h"
#include "engine/integrate/velocity_verlet.h"
#include "engine/models/dp_model.h"
#include "engine/protocol/hopper_run.h"
#include "engine/rng.h"

using namespace beverloo;

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s '<job json>' settle_t0 run_t0 speed factor...\n", argv[0]);
    return 2;
  }
  SimConfig c = SimConfig::from_json(nlohmann::json::parse(argv[1]));
  const double settle = std::atof(argv[2]), duration = std::atof(argv[3]), speed = std::atof(argv[4]);
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const double dt0 = run.time_step().dt;
  run.advance(static_cast<std::int64_t>(settle / dt0));
  auto& model = static_cast<DpModel&>(run.model());
  DpSystem& dp = model.system();
  const ParticleState<2> settled = dp.verts();
  std::printf("%d vertices, dt_auto %.4g (limited by %s)\n", settled.size(), dt0, run.time_step().period_term.c_str());
  std::printf("factor  dt          max|dE|/K0   end dE/K0\n");
  for (int k = 5; k < argc; ++k) {
    const double factor = std::atof(argv[k]), dt = factor * dt0;
    ParticleState<2>& s = dp.verts();
    s = settled;
    Rng rng(12345);
    for (auto& v : s.v) v = speed * Vec<2>(rng.uniform(-1, 1), rng.uniform(-1, 1));
    DpForceField& ff = dp.forces();
    ff.set_dissipation(false);
    ff.list().invalidate();
    ForceReport r = ff.compute(s);
    const double k0 = s.kinetic_energy(), e0 = k0 + r.potential();
    double worst = 0;
    const auto steps = std::llround(duration / dt);
    for (long long i = 0; i < steps; ++i) {
      r = velocity_verlet_step(s, ff, dt).forces;
      const double e = s.kinetic_energy() + r.potential();
      if (!std::isfinite(e)) {
        worst = INFINITY;
        break;
      }
      worst = std::max(worst, std::fabs(e - e0));
    }
    const double end = s.kinetic_energy() + r.potential() - e0;
    std::printf("%6.2f  %.4g  %.3e    %+.3e\n", factor, dt, worst / k0, end / k0);
    std::fflush(stdout);
  }
  return 0;
}
