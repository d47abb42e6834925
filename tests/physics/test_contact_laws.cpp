// The contact-law seam (engine/forces/contact_laws.h): every registered normal law is tested
// the same way (its force is minus its energy's gradient, it vanishes at contact onset, it
// repels, and its stiffness for dt "auto" bounds d^2U/dr^2 at every overlap); the Hertz law
// (hertz_normal.h), added through the seam, is tested in the engine: finite differences of the
// whole contact term, an elastic binary collision (energy and momentum), scalar width.
#include <gtest/gtest.h>

#include "engine/forces/contact_laws.h"
#include "engine/integrate/velocity_verlet.h"
#include "engine/models/sp_model.h"
#include "engine/parameters.h"
#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::random_state;
using testing::random_velocities;
using testing::small_config;

double law_energy(const NormalLawRow& law, double eps, double sigma, double r) {
  if (r >= sigma) return 0;
  double energy = 0, ov;
  law.force(eps, 1 / sigma, r, energy, ov);
  return energy;
}

TEST(ContactLaws, EveryLawsForceIsMinusItsEnergysGradient) {
  const double eps = 3.7, sigma = 1.2, h = 1e-6;
  for (const NormalLawRow& law : normal_laws()) {
    for (double ov = 0.002; ov < 0.95; ov *= 1.3) {
      const double r = sigma * (1 - ov);
      double energy = 0, ov_out;
      const double force = law.force(eps, 1 / sigma, r, energy, ov_out);
      EXPECT_NEAR(ov_out, ov, 1e-12) << law.name;
      EXPECT_GT(force, 0) << law.name << ": must repel";
      const double numeric = -(law_energy(law, eps, sigma, r + h) - law_energy(law, eps, sigma, r - h)) / (2 * h);
      EXPECT_NEAR(force, numeric, 1e-6 * std::max(1.0, force)) << law.name << " at overlap " << ov;
    }
    // continuous at contact onset: energy and force vanish as the overlap does
    double energy = 0, ov;
    const double r = sigma * (1 - 1e-9);
    EXPECT_LT(law.force(eps, 1 / sigma, r, energy, ov), 1e-7 * eps / sigma) << law.name;
    EXPECT_LT(energy, 1e-12 * eps) << law.name;
  }
}

TEST(ContactLaws, EveryLawsStiffnessBoundsItsCurvatureAtEveryOverlap) {
  const double eps = 2.5, sigma = 0.9, h = 1e-5;
  for (const NormalLawRow& law : normal_laws()) {
    const double k = law.stiffness(eps, sigma);
    double largest = 0;
    for (double ov = 0.001; ov <= 0.999; ov += 0.002) {
      const double r = sigma * (1 - ov);
      const double d2 = (law_energy(law, eps, sigma, r + h) - 2 * law_energy(law, eps, sigma, r) +
                         law_energy(law, eps, sigma, r - h)) / (h * h);
      EXPECT_LE(d2, k * (1 + 1e-4)) << law.name << " at overlap " << ov;
      largest = std::max(largest, d2);
    }
    // and it is the bound, not a copied safety factor: reached within 1 %
    EXPECT_GT(largest, 0.99 * k) << law.name;
  }
}

TEST(ContactLaws, TheJobFilesAllowedValuesAreTheRegistrysNames) {
  const ParamSpec* p = find_parameter("sp_contact_law");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(std::string(p->allowed), normal_law_names());
  for (const NormalLawRow& law : normal_laws()) {
    EXPECT_EQ(&normal_law(law.name), &law);
    const std::string quoted = std::string("\"").append(law.name).append("\"");
    EXPECT_NE(std::string(p->doc).find(quoted), std::string::npos) << law.name;
  }
  try {
    normal_law("hooke");
    FAIL() << "an unknown law was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "sp_contact_law");
    EXPECT_NE(std::string(e.what()).find("hertz"), std::string::npos) << e.what();
  }
}

template <int D>
SimConfig hertz_config(int n, double zeta = 0, double mu = 0) {
  SimConfig c = small_config(D, n, D == 2 ? 3.0 : 2.5, zeta, mu);
  c.sp_contact_law = "hertz";
  c.resolve_and_validate();
  return c;
}

/// Central differences of the contact term's energy for every coordinate of every particle.
template <int D>
void check_hertz_gradient(std::uint64_t seed) {
  const SimConfig c = hertz_config<D>(D == 2 ? 120 : 150);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed);
  ForceField<D> ff(c, h);
  ff.set_dissipation(false);
  SpContact<D>& contact = const_cast<SpContact<D>&>(ff.contact());
  ASSERT_EQ(contact.normal_law_row().name, "hertz");
  auto energy = [&] {
    ff.list().build(s, h);
    VecArray<D> f(s.size(), Vec<D>::Zero());
    return contact.accumulate(s, f).energy;
  };
  ff.list().build(s, h);
  VecArray<D> f(s.size(), Vec<D>::Zero());
  ASSERT_GT(contact.accumulate(s, f).energy, 0);
  const double step = 1e-6;
  for (int i = 0; i < s.size(); ++i)
    for (int d = 0; d < D; ++d) {
      const double keep = s.x[i][d];
      s.x[i][d] = keep + step;
      const double up = energy();
      s.x[i][d] = keep - step;
      const double down = energy();
      s.x[i][d] = keep;
      ASSERT_NEAR(f[i][d], -(up - down) / (2 * step), 2e-5 * std::max(1.0, std::fabs(f[i][d])))
          << "particle " << i << " component " << d;
    }
}
TEST(HertzContact, GradientMatchesEnergy2D) { check_hertz_gradient<2>(11); }
TEST(HertzContact, GradientMatchesEnergy3D) { check_hertz_gradient<3>(21); }

/// Pair forces are equal and opposite (with friction too), friction only removes energy.
template <int D>
void check_hertz_momentum(std::uint64_t seed) {
  const SimConfig c = hertz_config<D>(D == 2 ? 200 : 300, 0.7, 3.0);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed);
  random_velocities(s, seed + 1, 2.0);
  ForceField<D> ff(c, h);
  ff.list().build(s, h);
  SpContact<D>& contact = const_cast<SpContact<D>&>(ff.contact());
  VecArray<D> f(s.size(), Vec<D>::Zero());
  const TermOutput out = contact.accumulate(s, f);
  Vec<D> total = Vec<D>::Zero();
  double scale = 0;
  for (const auto& fi : f) total += fi, scale += fi.norm();
  ASSERT_GT(scale, 0);
  EXPECT_LT(total.norm(), 1e-12 * scale);
  EXPECT_LT(out.power, 0);
}
TEST(HertzContact, PairForcesConserveMomentum2D) { check_hertz_momentum<2>(31); }
TEST(HertzContact, PairForcesConserveMomentum3D) { check_hertz_momentum<3>(41); }

/// A small and a large particle collide (no gravity, no dissipation, far from the walls), head
/// on and off centre: the total energy stays constant through the contact to O(dt^2), the
/// collision is elastic (the relative speed comes back), and the momentum is unchanged.
template <int D>
void check_hertz_collision(double offset) {
  SimConfig c = hertz_config<D>(2);
  c.W = 60;
  c.E_sp = 1e4;
  c.resolve_and_validate();
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = testing::small_and_large<D>(c);
  const double m0 = s.sp.mass[0], m1 = s.sp.mass[1], reach = 0.5 * (s.sp.sigma[0] + s.sp.sigma[1]);
  Vec<D> up = Vec<D>::Zero(), along = Vec<D>::Zero(), side = Vec<D>::Zero();
  up[kUp<D>] = 20;
  along[0] = 1;
  side[1] = 1;  // across the line of approach (2D: up, 3D: y)
  s.x[0] = up - (0.5 * reach + 0.01) * along - 0.5 * offset * reach * side;
  s.x[1] = up + (0.5 * reach + 0.01) * along + 0.5 * offset * reach * side;
  const double v_rel = 2.0;
  s.v[0] = (v_rel * m1 / (m0 + m1)) * along;
  s.v[1] = (-v_rel * m0 / (m0 + m1)) * along;
  const Vec<D> p0 = m0 * s.v[0] + m1 * s.v[1];
  ForceField<D> ff(c, h);
  ff.set_gravity(0);
  ForceReport r = ff.compute(s);
  const double e0 = s.kinetic_energy() + r.potential();
  const double dt = 2e-5;
  bool touched = false;
  double worst = 0, deepest = 0;
  for (int k = 0; k < 2'000'000; ++k) {
    r = velocity_verlet_step(s, ff, dt).forces;
    worst = std::max(worst, std::fabs(s.kinetic_energy() + r.potential() - e0));
    deepest = std::max(deepest, r.max_overlap);
    const bool touching = (s.x[1] - s.x[0]).norm() < reach;
    if (touched && !touching) break;
    touched = touched || touching;
  }
  ASSERT_TRUE(touched);
  EXPECT_GT(deepest, 1e-3) << "the collision must compress the contact";
  EXPECT_LT(worst, 1e-5 * e0) << "energy through the contact, offset " << offset;
  const double relative_speed = (s.v[1] - s.v[0]).norm();
  EXPECT_NEAR(relative_speed, v_rel, 1e-5 * v_rel) << "elastic: the relative speed returns";
  EXPECT_LT((m0 * s.v[0] + m1 * s.v[1] - p0).norm(), 1e-12);
}
TEST(HertzContact, BinaryCollisionConservesEnergyAndMomentum2D) {
  check_hertz_collision<2>(0);
  check_hertz_collision<2>(0.5);
}
TEST(HertzContact, BinaryCollisionConservesEnergyAndMomentum3D) {
  check_hertz_collision<3>(0);
  check_hertz_collision<3>(0.5);
}

TEST(HertzContact, RunsAtScalarWidthAndItsStiffnessSetsDt) {
  SimConfig c = hertz_config<2>(100);
  c.E_w = 1;  // soft walls: the pairs set the shortest period
  c.resolve_and_validate();
  const Hopper<2> h = hopper_for<2>(c);
  ForceField<2> ff(c, h);
  EXPECT_EQ(const_cast<SpContact<2>&>(ff.contact()).set_simd_width(4), 1);
  // the shortest period: the small-small pair with k = (3/2) E_sp / sigma_s^2
  SimConfig harmonic = c;
  harmonic.sp_contact_law = "energy";
  const TimeScales hz = SpModel<2>::time_scales(c), hm = SpModel<2>::time_scales(harmonic);
  ASSERT_EQ(hz.period_term(), "E_sp (small-small contact)");
  ASSERT_EQ(hm.period_term(), "E_sp (small-small contact)");
  EXPECT_NEAR(hm.period_min() / hz.period_min(), std::sqrt(1.5), 1e-12);
}

}  // namespace
}  // namespace beverloo
