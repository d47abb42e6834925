// Diagnostic: how inelastic is one collision of two bodies (a small and a large one) of a job's
// model, without gravity or walls? Behind docs/validation.md's account of the friction-only
// DP/SP difference: kinetic friction between light DP vertices turns far less of a collision's
// energy into heat than SP friction at the same mu. The bodies approach along x at relative speed
// v_rel with impact parameter b (in units of the sum of their radii); each DP orientation is
// random (averages over `samples` orientations). Printed per speed, means over the samples:
//   e_n      normal restitution of the centre-of-mass velocities (along the line of centres at
//            first contact), -v_after.n / v_before.n
//   e_t      tangential ratio v_after.t / v_before.t (1: friction removed nothing tangentially)
//   lost     fraction of the bodies' centre-of-mass kinetic energy gone after the collision
//   dissip   fraction dissipated (by friction or drag); lost - dissip went into rotation,
//            shape vibration and shape energy (DP only; SP bodies have no internal motion)
// Usage: binary_collision '<job json>' b samples v_rel...
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/config.h"
#include "engine/dp/dp_system.h"
#include "engine/forces/force_field.h"
#include "engine/geometry/make_hopper.h"
#include "engine/models/model_time_step.h"
#include "engine/integrate/velocity_verlet.h"
#include "engine/rng.h"
#include "engine/units.h"
using namespace beverloo;

namespace {

struct Outcome {
  double e_n = 0, e_t = 0, lost = 0, dissipated = 0;
};

// Centre-of-mass position and velocity of each of the two bodies, and their total mass.
struct Bodies {
  Vec<2> x[2], v[2];
  double m[2];
};

// Bodies `first` and `second` of a body-level state (SP particles, or DP centroids from
// DpSystem::sync_bodies), in that order.
Bodies bodies_of(const ParticleState<2>& s, int first, int second) {
  Bodies b;
  for (int k = 0; k < 2; ++k) {
    const int m = k == 0 ? first : second;
    b.x[k] = s.x[m], b.v[k] = s.v[m], b.m[k] = s.mass(m);
  }
  return b;
}

double cm_kinetic(const Bodies& b) {
  return 0.5 * (b.m[0] * b.v[0].squaredNorm() + b.m[1] * b.v[1].squaredNorm());
}

// Runs one collision: `step` advances one step; `bodies` reads the centres; `touching` says
// whether a contact force acts; `energy` is the total (kinetic of every mass point plus
// potential), whose loss is the dissipated energy (exact up to the integrator's error, unlike a
// sum of power x dt with the step's predicted velocities).
template <class Step, class Read, class Touch, class Energy>
Outcome collide(Step step, Read bodies, Touch touching, Energy energy) {
  const Bodies before = bodies();
  const double e0 = energy();
  const Vec<2> v_rel0 = before.v[1] - before.v[0];
  Vec<2> n = Vec<2>::Zero();
  bool contact = false;
  int steps_apart = 0;
  for (long k = 0; k < 20'000'000; ++k) {
    step();
    const bool now = touching();
    if (now && !contact) {  // first contact: the line of centres
      const Bodies b = bodies();
      n = (b.x[1] - b.x[0]).normalized();
    }
    contact = contact || now;
    steps_apart = (contact && !now) ? steps_apart + 1 : 0;
    if (steps_apart > 2000) break;  // well after the last contact
  }
  const Bodies after = bodies();
  const Vec<2> v_rel1 = after.v[1] - after.v[0];
  const Vec<2> t(-n.y(), n.x());
  Outcome o;
  o.e_n = -v_rel1.dot(n) / v_rel0.dot(n);
  o.e_t = std::fabs(v_rel0.dot(t)) > 1e-9 * v_rel0.norm() ? v_rel1.dot(t) / v_rel0.dot(t) : NAN;
  const double k0 = cm_kinetic(before);
  o.lost = 1 - cm_kinetic(after) / k0;
  o.dissipated = (e0 - energy()) / k0;
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s '<job json>' b samples v_rel...\n", argv[0]);
    return 2;
  }
  SimConfig c = SimConfig::from_json(nlohmann::json::parse(argv[1]));
  c.N = 2;
  c.W = 400;  // walls far away
  c.resolve_and_validate();
  const double b_impact = std::atof(argv[2]);
  const int samples = std::atoi(argv[3]);
  const Hopper<2> hopper = make_hopper<2>(c);
  const double dt = choose_time_step(c).dt;
  const Vec<2> mid(0, 100);
  std::printf("model %s mu %g zeta %g E %g b %g dt %.3g\n", c.model.c_str(), c.mu, c.zeta,
              c.model == "sp" ? c.E_sp : c.dp.E_c, b_impact, dt);
  std::printf("%8s %8s %8s %8s %8s\n", "v_rel", "e_n", "e_t", "lost", "dissip");
  for (int a = 4; a < argc; ++a) {
    const double v_rel = std::atof(argv[a]);
    Outcome mean;
    int counted = 0;
    for (int sample = 0; sample < samples; ++sample) {
      Outcome o;
      if (c.model == "sp") {
        ParticleState<2> s;
        s.sp = Species::bidisperse(2, c.size_ratio);
        s.resize(2);
        s.species = {0, 1};
        const double reach = 0.5 * (s.sp.sigma[0] + s.sp.sigma[1]);
        for (int k = 0; k < 2; ++k) s.inv_mass[k] = 1 / s.mass(k);
        s.x[0] = mid - Vec<2>(0.5 * reach + 0.05, 0.5 * b_impact * reach);
        s.x[1] = mid + Vec<2>(0.5 * reach + 0.05, 0.5 * b_impact * reach);
        // centre-of-mass frame
        const double m0 = s.mass(0), m1 = s.mass(1);
        s.v[0] = Vec<2>(v_rel * m1 / (m0 + m1), 0);
        s.v[1] = Vec<2>(-v_rel * m0 / (m0 + m1), 0);
        ForceField<2> ff(c, hopper);
        ff.set_gravity(0);
        ForceReport last = ff.compute(s);
        o = collide([&] { last = velocity_verlet_step(s, ff, dt).forces; }, [&] { return bodies_of(s, 0, 1); },
                    [&] { return (s.x[1] - s.x[0]).norm() < reach; },
                    [&] { return s.kinetic_energy() + last.potential(); });
      } else {
        DpSystem dp(c, hopper);
        ParticleState<2> seed_bodies;
        Rng rng(1000 + sample);
        dp.place_bodies(seed_bodies, rng);
        dp.build_polygons(seed_bodies, rng);
        const DpShape& sh = dp.shape();
        const int small = seed_bodies.species[0] == 0 ? 0 : 1;  // polygon index of the small body
        const int large = 1 - small;
        const double reach = sh.circumradius[0] + sh.circumradius[1] + 0.5 * (sh.delta[0] + sh.delta[1]);
        const double m_s = seed_bodies.sp.mass[0], m_l = seed_bodies.sp.mass[1];
        const double angle_s = rng.uniform() * 2 * units::pi, angle_l = rng.uniform() * 2 * units::pi;
        dp.reinject(small, mid - Vec<2>(0.5 * reach + 0.05, 0.5 * b_impact * reach), Vec<2>(v_rel * m_l / (m_s + m_l), 0),
                    angle_s);
        dp.reinject(large, mid + Vec<2>(0.5 * reach + 0.05, 0.5 * b_impact * reach), Vec<2>(-v_rel * m_s / (m_s + m_l), 0),
                    angle_l);
        dp.forces().set_gravity(0);
        ForceReport last = dp.forces().compute(dp.verts());
        // bodies read as (small, large), so that the normal points from small to large as for SP
        auto read = [&] {
          dp.sync_bodies(seed_bodies);
          return bodies_of(seed_bodies, small, large);
        };
        o = collide([&] { last = velocity_verlet_step(dp.verts(), dp.forces(), dt).forces; }, read,
                    [&] { return last.U_contact > 0; }, [&] { return dp.verts().kinetic_energy() + last.potential(); });
      }
      if (std::isfinite(o.e_n)) {
        mean.e_n += o.e_n, mean.e_t += o.e_t, mean.lost += o.lost, mean.dissipated += o.dissipated;
        ++counted;
      }
    }
    std::printf("%8.3g %8.3f %8.3f %8.3f %8.3f\n", v_rel, mean.e_n / counted, mean.e_t / counted, mean.lost / counted,
                mean.dissipated / counted);
  }
}
