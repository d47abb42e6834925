// The time step's margin for DP, measured: a DP pile settled under gravity with the job's drag
// in a closed hopper, then without any dissipation and with random vertex velocities, run
// conservatively at dt_auto times each given factor. Printed per factor: the largest |E(t) -
// E(0)| over the run relative to the initial kinetic energy, and at the end. Velocity Verlet's
// error should scale as dt^2 until the step stops resolving the stiffest term.
// A factor written jF (e.g. j0.125) also prints the 5 steps with the largest |dE| (relative to
// K0) and which energies changed in them: a jump that keeps its size when dt is halved is a
// discontinuity of the energy, not an integration error. A factor written cF checks the list
// at every step: the energies recomputed from a freshly built list must equal the running
// list's (a difference is a contact the list missed).
// Usage: dp_energy_drift '<job json>' settle_t0 run_t0 speed factor...
#include <chrono>
#include <algorithm>
#include <cmath>
#include <vector>
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
    const bool jumps = argv[k][0] == 'j', check = argv[k][0] == 'c';
    const double factor = std::atof(argv[k] + (jumps || check ? 1 : 0)), dt = factor * dt0;
    long long mismatches = 0;
    double worst_mismatch = 0;
    struct Step {
      double dE, dK, dU_contact, dU_wall, dU_shape, dU_gravity, t;
    };
    std::vector<Step> largest;
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
    ForceReport before = r;
    double e_before = e0, k_before = k0;
    for (long long i = 0; i < steps; ++i) {
      r = velocity_verlet_step(s, ff, dt).forces;
      const double kin = s.kinetic_energy(), e = kin + r.potential();
      if (check) {
        ff.list().invalidate();
        const ForceReport fresh = ff.compute(s);
        const double diff = std::fabs(fresh.potential() - r.potential());
        if (diff > 1e-12 * (1 + std::fabs(r.potential()))) {
          ++mismatches;
          if (diff > worst_mismatch)
            std::printf("   t = %.5f: fresh list U_contact %+.6e, running %+.6e (U_wall %+.3e vs %+.3e)\n", (i + 1) * dt,
                        fresh.U_contact, r.U_contact, fresh.U_wall, r.U_wall);
          worst_mismatch = std::max(worst_mismatch, diff);
        }
      }
      if (jumps) {
        largest.push_back({std::fabs(e - e_before), kin - k_before, r.U_contact - before.U_contact,
                           r.U_wall - before.U_wall, r.U_shape - before.U_shape, r.U_gravity - before.U_gravity,
                           (i + 1) * dt});
        std::sort(largest.begin(), largest.end(), [](const Step& a, const Step& b) { return a.dE > b.dE; });
        if (largest.size() > 5) largest.pop_back();
        before = r;
        e_before = e;
        k_before = kin;
      }
      if (!std::isfinite(e)) {
        worst = INFINITY;
        break;
      }
      worst = std::max(worst, std::fabs(e - e0));
    }
    const double end = s.kinetic_energy() + r.potential() - e0;
    std::printf("%6.2f  %.4g  %.3e    %+.3e\n", factor, dt, worst / k0, end / k0);
    if (check) std::printf("   steps whose fresh list gave another energy: %lld (largest difference %.3e K0)\n", mismatches, worst_mismatch / k0);
    for (const Step& j : largest)
      std::printf("   jump at t = %.5f: |dE| %.3e K0; dK %+.3e dU_contact %+.3e dU_wall %+.3e dU_shape %+.3e dU_gravity %+.3e\n",
                  j.t, j.dE / k0, j.dK / k0, j.dU_contact / k0, j.dU_wall / k0, j.dU_shape / k0, j.dU_gravity / k0);
    std::fflush(stdout);
  }
  return 0;
}
