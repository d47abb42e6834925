// Generic physics tests run on every force term of the force field (style.md lesson 6):
// analytic forces equal minus the finite-difference gradient of the term's energy; pair terms
// conserve momentum; dissipative terms never add energy.
#include <gtest/gtest.h>

#include "support.h"

namespace beverloo {
namespace {
using testing::hopper_for;
using testing::random_state;
using testing::random_velocities;
using testing::small_config;

template <int D>
double term_energy(ForceTerm<D>* term, ForceField<D>& ff, ParticleState<D>& s, const Hopper<D>& h) {
  ff.list().build(s, h);
  VecArray<D> f(s.size(), Vec<D>::Zero());
  return term->accumulate(s, f).energy;
}

/// Central differences of every conservative term for every coordinate of every particle.
template <int D>
void check_gradients(const SimConfig& c, ParticleState<D> s, int* terms_with_energy) {
  const Hopper<D> h = hopper_for<D>(c);
  ForceField<D> ff(c, h);
  ff.set_dissipation(false);
  for (auto& v : s.v) v.setZero();
  for (ForceTerm<D>* term : ff.terms()) {
    ff.list().build(s, h);
    VecArray<D> f(s.size(), Vec<D>::Zero());
    const double e0 = term->accumulate(s, f).energy;
    if (e0 != 0) ++*terms_with_energy;
    const double eps = 1e-6;
    for (int i = 0; i < s.size(); ++i) {
      for (int d = 0; d < D; ++d) {
        const double keep = s.x[i][d];
        s.x[i][d] = keep + eps;
        const double up = term_energy(term, ff, s, h);
        s.x[i][d] = keep - eps;
        const double down = term_energy(term, ff, s, h);
        s.x[i][d] = keep;
        const double numeric = -(up - down) / (2 * eps);
        const double scale = std::max(1.0, std::fabs(f[i][d]));
        ASSERT_NEAR(f[i][d], numeric, 2e-5 * scale)
            << term->name() << " particle " << i << " component " << d << " at " << s.x[i].transpose();
      }
    }
  }
}

TEST(ForceTerms, GradientMatchesEnergy2D) {
  SimConfig c = small_config(2, 120, 3.0);
  c.gravity = 1;
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 11);
  // push some particles against the funnel and side walls and into the orifice
  for (int i = 0; i < 12; ++i) s.x[i] = Vec<2>(-5.7 + 0.9 * i, 0.3 + 0.05 * i);
  int with_energy = 0;
  check_gradients<2>(c, s, &with_energy);
  EXPECT_EQ(with_energy, 3);  // contact, walls and gravity all had work to do
}

TEST(ForceTerms, GradientMatchesEnergy2DSlantedAsymmetricFunnel) {
  SimConfig c = small_config(2, 60, 2.5);
  c.theta_w_left_deg = 30;
  c.theta_w_right_deg = 60;
  c.resolve_and_validate();
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 12);
  // particles on both funnel walls (inside, overlapping them)
  for (int k = 0; k < 6; ++k) {
    const double y = 0.5 + 0.8 * k;
    s.x[k] = Vec<2>(-1.25 - y * std::tan(units::deg_to_rad(30)) + 0.2, y);
    s.x[6 + k] = Vec<2>(1.25 + y * std::tan(units::deg_to_rad(60)) - 0.2, y);
  }
  int with_energy = 0;
  check_gradients<2>(c, s, &with_energy);
  EXPECT_EQ(with_energy, 3);
}

TEST(ForceTerms, GradientMatchesEnergy2DWithAVerticalWall) {
  // The experiments' 45/0 hopper, both ways round: the vertical wall is a ray from its orifice
  // edge (the corner) up, and it is the container's side; the slanted wall spans W - w.
  for (const bool right_vertical : {true, false}) {
    SimConfig c = small_config(2, 60, 2.5);
    c.theta_w_left_deg = right_vertical ? 45 : 0;
    c.theta_w_right_deg = right_vertical ? 0 : 45;
    c.resolve_and_validate();
    const Hopper<2> h = hopper_for<2>(c);
    ParticleState<2> s = random_state<2>(c, h, 14);
    const double sign = right_vertical ? 1 : -1;  // the vertical wall's side
    for (int k = 0; k < 5; ++k) {
      const double y = 0.4 + 1.1 * k;
      s.x[k] = Vec<2>(sign * (1.25 - 0.3), y);                   // against the vertical wall
      s.x[5 + k] = Vec<2>(-sign * (1.25 + y - 0.25), y + 0.05);  // on the 45-degree wall
    }
    s.x[10] = Vec<2>(sign * (1.25 - 0.2), 0.1);   // at the vertical wall's corner, inside the orifice
    s.x[11] = Vec<2>(sign * (1.25 + 0.2), -0.2);  // below the corner after exiting
    int with_energy = 0;
    check_gradients<2>(c, s, &with_energy);
    EXPECT_EQ(with_energy, 3) << (right_vertical ? "45/0" : "0/45");
  }
}

TEST(ForceTerms, GradientAtOrificeCorner2D) {
  // Particles whose nearest wall point is the end point of a funnel segment (the orifice
  // edge): above it, beside it inside the orifice, and below it after exiting.
  SimConfig c = small_config(2, 4, 3.0);
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 13);
  s.x[0] = Vec<2>(1.5 - 0.25, 0.2);   // inside the orifice, touching the right corner
  s.x[1] = Vec<2>(-1.5 + 0.2, -0.15); // below the plane, touching the left corner
  s.x[2] = Vec<2>(1.5 + 0.1, -0.3);   // under the right wall's end
  s.x[3] = Vec<2>(-4.0, 5.0);         // free
  const Vec<2> corner(1.5, 0);
  EXPECT_EQ(h.nearest_point(1, s.x[0]), corner);
  int with_energy = 0;
  check_gradients<2>(c, s, &with_energy);
  EXPECT_GE(with_energy, 1);
}

TEST(ForceTerms, GradientMatchesEnergy3D) {
  SimConfig c = small_config(3, 150, 2.5);
  const Hopper<3> h = hopper_for<3>(c);
  ParticleState<3> s = random_state<3>(c, h, 21);
  // against the mantle, on the base, at the orifice rim (the corner) from above and below
  s.x[0] = Vec<3>(3.8, 0.0, 2.0);
  s.x[1] = Vec<3>(0.0, -3.75, 0.3);
  s.x[2] = Vec<3>(2.0, 1.0, 0.2);
  s.x[3] = Vec<3>(1.25 - 0.2, 0.0, 0.15);
  s.x[4] = Vec<3>(0.0, 1.25 - 0.1, -0.2);
  s.x[5] = Vec<3>(0.7, 0.8, 0.1);  // rim from inside, off-axis
  int with_energy = 0;
  check_gradients<3>(c, s, &with_energy);
  EXPECT_EQ(with_energy, 3);
}

template <int D>
void check_momentum_and_dissipation(int n, std::uint64_t seed) {
  SimConfig c = small_config(D, n, 2.0, /*zeta=*/0.7, /*mu=*/3.0);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed);
  random_velocities(s, seed + 1, 2.0);
  ForceField<D> ff(c, h);
  ff.list().build(s, h);
  // contact term alone: repulsion plus friction, pairwise equal and opposite
  SpContact<D>& contact = *static_cast<SpContact<D>*>(ff.terms()[0]);
  VecArray<D> f(s.size(), Vec<D>::Zero());
  const TermOutput out = contact.accumulate(s, f);
  Vec<D> total = Vec<D>::Zero();
  double scale = 0;
  for (const auto& fi : f) {
    total += fi;
    scale += fi.norm();
  }
  ASSERT_GT(scale, 0);
  EXPECT_LT(total.norm(), 1e-12 * scale) << "net contact force " << total.transpose();
  EXPECT_LT(out.power, 0) << "friction must remove energy";
  // friction alone: also zero net force, and its power equals the reported one
  VecArray<D> ffr;
  contact.friction_forces(s, ffr);
  Vec<D> net = Vec<D>::Zero();
  double power = 0;
  for (int i = 0; i < s.size(); ++i) {
    net += ffr[i];
    power += ffr[i].dot(s.v[i]);
  }
  EXPECT_LT(net.norm(), 1e-12 * scale);
  EXPECT_NEAR(power, out.power, 1e-9 * std::fabs(out.power));
  // drag: power -zeta sum v^2 < 0
  VecArray<D> fd(s.size(), Vec<D>::Zero());
  EXPECT_LT(ff.terms()[3]->accumulate(s, fd).power, 0);
}

TEST(ForceTerms, PairForcesConserveMomentumAndDissipationRemovesEnergy2D) { check_momentum_and_dissipation<2>(200, 31); }
TEST(ForceTerms, PairForcesConserveMomentumAndDissipationRemovesEnergy3D) { check_momentum_and_dissipation<3>(300, 41); }

TEST(ForceTerms, FrictionActsOnFullRelativeVelocity) {
  // Two overlapping particles sliding tangentially: friction opposes the tangential motion
  // (a normal-only friction would give zero here).
  SimConfig c = small_config(2, 2, 2.0, 0, 2.0);
  const Hopper<2> h = hopper_for<2>(c);
  ParticleState<2> s = random_state<2>(c, h, 5);
  s.x[0] = Vec<2>(0, 5);
  s.x[1] = Vec<2>(0.9, 5);
  s.v[0] = Vec<2>(0, 1);
  s.v[1] = Vec<2>(0, -1);
  ForceField<2> ff(c, h);
  ff.list().build(s, h);
  VecArray<2> f;
  ff.contact().friction_forces(s, f);
  EXPECT_DOUBLE_EQ(f[0][1], -2.0 * 2.0);
  EXPECT_DOUBLE_EQ(f[1][1], 2.0 * 2.0);
}

}  // namespace
}  // namespace beverloo
