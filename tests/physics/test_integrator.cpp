// Velocity Verlet: energy conserved to O(dt^2) without dissipation; dissipation never adds energy.
#include <gtest/gtest.h>

#include "engine/integrate/velocity_verlet.h"
#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::random_state;
using testing::random_velocities;
using testing::small_config;

template <int D>
ParticleState<D> settled_closed_hopper(const SimConfig& c, const Hopper<D>& h, double gravity = 0) {
  // an orifice far narrower than the small particles: nothing can leave, the system is closed
  ParticleState<D> s = random_state<D>(c, h, 3);
  ForceField<D> ff(c, h);
  ff.set_gravity(gravity);
  ff.set_dissipation(false);
  const FireResult fr = fire_minimize(s, ff, c.fire, 1e-3);
  EXPECT_TRUE(fr.converged);
  return s;
}

/// Largest |E(t) - E(0)| over `duration` from state s with zeta = mu = 0.
template <int D>
double max_energy_error(const SimConfig& c, ParticleState<D> s, double dt, double duration) {
  const Hopper<D> h = hopper_for<D>(c);
  ForceField<D> ff(c, h);
  ForceReport r = ff.compute(s);
  const double e0 = s.kinetic_energy() + r.potential();
  double worst = 0;
  const auto steps = std::llround(duration / dt);
  for (long long k = 0; k < steps; ++k) {
    r = velocity_verlet_step(s, ff, dt).forces;
    worst = std::max(worst, std::fabs(s.kinetic_energy() + r.potential() - e0));
  }
  return worst;
}

template <int D>
void check_energy_conservation(int n) {
  // A pile settled under gravity and shaken with random velocities: contacts open and close.
  // Each contact onset is a kink in the force's derivative, so a single trajectory's error
  // depends on where in a step the onsets fall; averaged over seeds, log(error) against
  // log(dt) has slope 2 (measured 1.99 - 2.23 for 2D and 3D over dt = 2e-3 .. 2.5e-4).
  SimConfig c = small_config(D, n, 0.3);
  const Hopper<D> h = hopper_for<D>(c);
  const ParticleState<D> pile = settled_closed_hopper<D>(c, h, 1.0);
  const double dts[3] = {2e-3, 1e-3, 5e-4};
  double mean_error[3] = {0, 0, 0};
  const int seeds = 4;
  double kinetic = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    ParticleState<D> s = pile;
    random_velocities(s, 100 + seed, 0.3);
    kinetic += s.kinetic_energy() / seeds;
    for (int k = 0; k < 3; ++k) mean_error[k] += max_energy_error<D>(c, s, dts[k], 1.0) / seeds;
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < 3; ++k) {
    const double x = std::log(dts[k]), y = std::log(mean_error[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double slope = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
  EXPECT_LT(mean_error[1], 1e-2 * kinetic) << "energy error at dt = 1e-3 against kinetic energy " << kinetic;
  EXPECT_GT(slope, 1.75) << "energy error must scale as dt^2";
  EXPECT_LT(slope, 2.4) << "energy error must scale as dt^2";
}

TEST(VelocityVerlet, EnergyConservedAndErrorScalesAsDtSquared2D) { check_energy_conservation<2>(120); }
TEST(VelocityVerlet, EnergyConservedAndErrorScalesAsDtSquared3D) { check_energy_conservation<3>(150); }

template <int D>
void check_dissipation_never_adds_energy(double zeta, double mu) {
  SimConfig c = small_config(D, 150, 0.3, zeta, mu);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = settled_closed_hopper<D>(c, h);
  random_velocities(s, 17, 2.0);
  ForceField<D> ff(c, h);
  ForceReport r = ff.compute(s);
  double e_prev = s.kinetic_energy() + r.potential();
  const double e_start = e_prev;
  // The conservative part's own O(dt^2) fluctuation bounds any apparent increase.
  const double tol = 1e-6 * std::fabs(e_start) + 1e-6;
  for (int k = 0; k < 3000; ++k) {
    const StepReport rep = velocity_verlet_step(s, ff, 1e-3);
    EXPECT_LE(rep.forces.P_drag + rep.forces.P_friction, 0.0);
    const double e = s.kinetic_energy() + rep.forces.potential();
    ASSERT_LE(e, e_prev + tol) << "energy grew at step " << k;
    e_prev = e;
  }
  EXPECT_LT(e_prev, e_start);
}

TEST(Dissipation, DragOnlyNeverAddsEnergy2D) { check_dissipation_never_adds_energy<2>(0.5, 0); }
TEST(Dissipation, FrictionOnlyNeverAddsEnergy2D) { check_dissipation_never_adds_energy<2>(0, 10.0); }
TEST(Dissipation, FrictionOnlyNeverAddsEnergy3D) { check_dissipation_never_adds_energy<3>(0, 10.0); }

/// Normal restitution of a head-on collision of a small and a large particle (friction only,
/// far from the walls, no gravity). During the contact the relative coordinate is a damped
/// linear oscillator, mu_r x'' = -k x - mu x' with k = E_sp/sigma_mn^2 (U = (E/2)(1 - r/s)^2)
/// and mu_r the reduced mass (friction acts on the full relative velocity of both particles),
/// and the contact ends at x = 0 after half a damped period: e = exp(-pi z / sqrt(1 - z^2)),
/// z = mu / (2 sqrt(k mu_r)). The DP comparison in docs/validation.md rests on this number.
template <int D>
void check_head_on_restitution(double E_sp, double mu) {
  SimConfig c = small_config(D, 2, 1.0, 0, mu);
  c.W = 60;
  c.E_sp = E_sp;
  c.resolve_and_validate();
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = testing::small_and_large<D>(c);
  const double m0 = s.sp.mass[0], m1 = s.sp.mass[1], reach = 0.5 * (s.sp.sigma[0] + s.sp.sigma[1]);
  Vec<D> up = Vec<D>::Zero(), along = Vec<D>::Zero();
  up[kUp<D>] = 20;
  along[0] = 1;
  s.x[0] = up - (0.5 * reach + 0.01) * along;
  s.x[1] = up + (0.5 * reach + 0.01) * along;
  const double v_rel = 0.7;
  s.v[0] = (v_rel * m1 / (m0 + m1)) * along;  // centre-of-mass frame
  s.v[1] = (-v_rel * m0 / (m0 + m1)) * along;
  ForceField<D> ff(c, h);
  ff.set_gravity(0);
  ff.compute(s);
  const double dt = 1e-5;
  bool touched = false;
  for (int k = 0; k < 1'000'000; ++k) {
    velocity_verlet_step(s, ff, dt);
    const bool touching = (s.x[1] - s.x[0]).norm() < reach;
    if (touched && !touching) break;
    touched = touched || touching;
  }
  ASSERT_TRUE(touched);
  const double e = (s.v[1] - s.v[0]).dot(along) / v_rel;  // they approached at -v_rel
  const double k = E_sp / (reach * reach), mu_r = m0 * m1 / (m0 + m1), z = mu / (2 * std::sqrt(k * mu_r));
  ASSERT_LT(z, 1);
  EXPECT_NEAR(e, std::exp(-units::pi * z / std::sqrt(1 - z * z)), 2e-3) << "z = " << z;
  // and the momentum is the centre-of-mass frame's, zero
  EXPECT_LT((m0 * s.v[0] + m1 * s.v[1]).norm(), 1e-12);
}

TEST(Dissipation, HeadOnFrictionalCollisionIsADampedOscillator2D) {
  check_head_on_restitution<2>(1e5, 10 * std::sqrt(10.0));
  check_head_on_restitution<2>(1e4, 10.0);
}
TEST(Dissipation, HeadOnFrictionalCollisionIsADampedOscillator3D) { check_head_on_restitution<3>(1e5, 30.0); }

}  // namespace
}  // namespace beverloo
