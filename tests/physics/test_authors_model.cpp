// The model as the paper's authors ran it (physics.md 10, docs/authors-model.md): kinetic
// friction split into normal and tangential parts, drag as a rate times the mass, the smooth
// DP contact width. Each test would fail if the option were wired wrongly.
#include <gtest/gtest.h>

#include "dp_support.h"
#include "engine/models/model_time_step.h"
#include "engine/integrate/velocity_verlet.h"
#include "support.h"

namespace beverloo {
namespace {
using testing::dp_config;
using testing::DpFixture;
using testing::hopper_for;
using testing::random_state;
using testing::random_velocities;
using testing::small_config;

SimConfig split(SimConfig c, double mu_n, double mu_t) {
  c.mu_n = mu_n;
  c.mu_t = mu_t;
  c.resolve_and_validate();
  return c;
}

// --- friction split: momentum and the sign of the dissipation, every contact law ---------------

template <int D>
void check_split_friction_momentum_and_power(double mu_n, double mu_t, std::uint64_t seed) {
  const SimConfig c = split(small_config(D, D == 2 ? 200 : 300, 2.0, 0.0, 3.0), mu_n, mu_t);
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = random_state<D>(c, h, seed);
  random_velocities(s, seed + 1, 2.0);
  ForceField<D> ff(c, h);
  ff.list().build(s, h);
  VecArray<D> f;
  ff.contact().friction_forces(s, f);
  Vec<D> net = Vec<D>::Zero();
  double power = 0, scale = 0, normal_power = 0;
  for (int i = 0; i < s.size(); ++i) {
    net += f[i];
    power += f[i].dot(s.v[i]);
    scale += f[i].norm();
  }
  ASSERT_GT(scale, 0);
  EXPECT_LT(net.norm(), 1e-12 * scale) << "split friction must be pairwise equal and opposite";
  EXPECT_LT(power, 0) << "split friction must remove energy";
  // the power equals the analytic sum -mu_n (dv.n)^2 - mu_t |dv_t|^2 over overlapping pairs
  double expected = 0;
  for (int i = 0; i < s.size(); ++i)
    for (int j = i + 1; j < s.size(); ++j) {
      const Vec<D> dx = s.x[i] - s.x[j];
      const double sig = 0.5 * (s.sigma(i) + s.sigma(j));
      if (dx.squaredNorm() >= sig * sig) continue;
      const Vec<D> n = dx.normalized(), dv = s.v[i] - s.v[j];
      const double vn = dv.dot(n);
      expected += -mu_n * vn * vn - mu_t * (dv - vn * n).squaredNorm();
      normal_power += -mu_n * vn * vn;
    }
  EXPECT_NEAR(power, expected, 1e-9 * std::fabs(expected));
  if (mu_n == 0) {
    EXPECT_EQ(normal_power, 0);
  }
  // and the combined contact pass reports the same power
  VecArray<D> fc(s.size(), Vec<D>::Zero());
  EXPECT_NEAR(ff.terms()[0]->accumulate(s, fc).power, expected, 1e-9 * std::fabs(expected));
}

TEST(AuthorsModel, SplitFrictionConservesMomentumAndOnlyRemovesEnergy2D) {
  check_split_friction_momentum_and_power<2>(0.0, 3.0, 31);
  check_split_friction_momentum_and_power<2>(1.0, 3.0, 32);
  check_split_friction_momentum_and_power<2>(3.0, 0.5, 33);
}
TEST(AuthorsModel, SplitFrictionConservesMomentumAndOnlyRemovesEnergy3D) {
  check_split_friction_momentum_and_power<3>(0.0, 3.0, 41);
}

TEST(AuthorsModel, EqualSplitIsTheTextsFullFrictionAndLeavesTheJobUnchanged) {
  const SimConfig full = small_config(2, 2, 2.0, 0.0, 2.0);
  const SimConfig same = split(full, 2.0, 2.0);
  EXPECT_FALSE(same.mu_n.has_value()) << "a split equal to mu is no split";
  EXPECT_EQ(same.to_json().dump(), full.to_json().dump());
  // a nonzero normal part changes the job, and the normal-only law gives the normal force
  const SimConfig tangential = split(full, 0.0, 2.0);
  EXPECT_NE(tangential.to_json().dump(), full.to_json().dump());
  const FrictionLaw law{0.0, 2.0};
  const Vec<2> n(1, 0), v_m(-1.0, 0.5), v_n(0.0, 0.0);
  const Vec<2> ff = kinetic_friction_force<2>(law, v_m, v_n, n);
  EXPECT_DOUBLE_EQ(ff[0], 0.0) << "no friction along the normal";
  EXPECT_DOUBLE_EQ(ff[1], -2.0 * 0.5);
}

TEST(AuthorsModel, SplitFrictionOnDpContactsConservesMomentumAndOnlyRemovesEnergy) {
  const std::vector<Vec<2>> centres = {{-0.45, 3.0}, {0.45, 3.05}, {0.0, 3.8}, {-0.9, 3.8}, {0.9, 3.75}};
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    SimConfig c = dp_config(model, 5, 0.0, 3.0);
    c.mu_n = 0.0;
    c.resolve_and_validate();
    DpFixture fx(c, centres, 0.2, 7);
    random_velocities(fx.verts, 8, 1.0);
    const Hopper<2> h = make_hopper<2>(fx.c);
    DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
    ff.list().build(fx.verts, h);
    VecArray<2> fr;
    ff.friction_forces(fx.verts, fr);
    Vec<2> net = Vec<2>::Zero();
    double power = 0, scale = 0;
    for (int i = 0; i < fx.verts.size(); ++i) {
      net += fr[i];
      power += fr[i].dot(fx.verts.v[i]);
      scale += fr[i].norm();
    }
    ASSERT_GT(scale, 0) << model << ": the polygons must touch";
    EXPECT_LT(net.norm(), 1e-11 * scale) << model;
    EXPECT_LT(power, 0) << model;
  }
}

TEST(AuthorsModel, SmoothDpTangentialFrictionIgnoresMotionAlongTheEdgeNormal) {
  // One vertex of polygon 1 pressed into an edge of polygon 0: moving straight into the edge it
  // feels no tangential friction, sliding along the edge it feels -mu_t v.
  SimConfig c = dp_config("dp_smooth", 2, 0.0, 4.0);
  c.mu_n = 0.0;
  c.resolve_and_validate();
  DpFixture fx(c, {{0.0, 3.0}, {5.0, 3.0}}, 0.0, 1);
  // put a vertex of polygon 1 just inside the width of the midpoint of edge (first[0], next)
  const int a = fx.poly.first[0], an = fx.poly.next[a];
  const Vec<2> e = fx.verts.x[an] - fx.verts.x[a];
  const Vec<2> nhat = Vec<2>(e[1], -e[0]).normalized();  // outward (counter-clockwise polygon)
  const int b = fx.poly.first[1];
  const Vec<2> shift = 0.5 * (fx.verts.x[a] + fx.verts.x[an]) + 0.5 * fx.shape.delta[0] * nhat - fx.verts.x[b];
  for (int i = fx.poly.first[1]; i < fx.poly.first[2]; ++i) fx.verts.x[i] += shift;
  const Hopper<2> h = make_hopper<2>(fx.c);
  DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
  ff.list().build(fx.verts, h);
  for (auto& v : fx.verts.v) v.setZero();
  VecArray<2> fr;
  fx.verts.v[b] = -0.3 * nhat;  // into the edge
  ff.friction_forces(fx.verts, fr);
  EXPECT_LT(fr[b].norm(), 1e-12);
  const Vec<2> that = e.normalized();
  fx.verts.v[b] = 0.3 * that;  // along the edge
  ff.friction_forces(fx.verts, fr);
  EXPECT_NEAR(fr[b].dot(that), -4.0 * 0.3, 1e-12);
  EXPECT_NEAR(fr[b].dot(nhat), 0.0, 1e-12);
  // the edge's end vertices take the reaction by the lever rule (here one half each)
  EXPECT_NEAR(fr[a].dot(that), 0.5 * 4.0 * 0.3, 1e-9);
  EXPECT_NEAR(fr[an].dot(that), 0.5 * 4.0 * 0.3, 1e-9);
}

// --- the authors' SP contact: a constant force scale ---------------------------------------------

TEST(AuthorsModel, ForceLawContactScalesTheEnergyWithTheContactDiameterAndMatchesItsGradient) {
  SimConfig c = small_config(2, 2, 2.0);
  c.E_sp = 140;
  c.sp_contact_law = "force";
  c.resolve_and_validate();
  const Hopper<2> h = hopper_for<2>(c);
  for (int sa : {0, 1})
    for (int sb : {0, 1}) {
      ParticleState<2> s;
      s.sp = Species::bidisperse(2, c.size_ratio);
      s.resize(2);
      s.species = {std::uint8_t(sa), std::uint8_t(sb)};
      const double sig = 0.5 * (s.sp.sigma[sa] + s.sp.sigma[sb]);
      s.x[0] = Vec<2>(0.0, 5.0);
      s.x[1] = Vec<2>(0.8 * sig, 5.0);
      ForceField<2> ff(c, h);
      ff.list().build(s, h);
      VecArray<2> f(2, Vec<2>::Zero());
      const double e = ff.terms()[0]->accumulate(s, f).energy;
      // U = (E_sp sigma_mn / 2)(1 - r/sigma_mn)^2: the force E_sp (1 - r/sigma_mn), as spK in the code
      EXPECT_NEAR(e, 0.5 * 140 * sig * 0.2 * 0.2, 1e-12) << sa << sb;
      EXPECT_NEAR(f[1][0], 140 * 0.2, 1e-10) << "the force scale is the same for every pair";
      // central differences
      const double eps = 1e-6;
      for (int d = 0; d < 2; ++d) {
        auto energy_at = [&](double shift) {
          ParticleState<2> t = s;
          t.x[1][d] += shift;
          ff.list().build(t, h);
          VecArray<2> g(2, Vec<2>::Zero());
          return ff.terms()[0]->accumulate(t, g).energy;
        };
        EXPECT_NEAR(f[1][d], -(energy_at(eps) - energy_at(-eps)) / (2 * eps), 1e-6);
      }
    }
  // and the time step follows the stiffest pair (large-large: the largest energy per sigma^2 is
  // the small pair's, E sigma / sigma^2)
  SimConfig text = c;
  text.sp_contact_law = "energy";
  EXPECT_GT(choose_time_step(c).period_min, choose_time_step(text).period_min * 0.999)
      << "E_sp sigma_mn with sigma_mn < 1 for the small pair: softer than E_sp";
}

// --- collisions: what the split takes and what it leaves ---------------------------------------

struct Collision {
  double e_normal;      ///< normal restitution
  double tangential;    ///< |tangential relative velocity| after / before
};

/// A small and a large particle meet at relative velocity (v_n, v_t) in the centre-of-mass
/// frame, no gravity, no drag, far from walls; integrated until they separate.
template <int D>
Collision collide(double E_sp, double mu, std::optional<double> mu_n, std::optional<double> mu_t, double v_n,
                  double v_t) {
  SimConfig c = small_config(D, 2, 1.0, 0, mu);
  c.W = 60;
  c.E_sp = E_sp;
  c.mu_n = mu_n;
  c.mu_t = mu_t;
  c.resolve_and_validate();
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = testing::small_and_large<D>(c);
  const double m0 = s.sp.mass[0], m1 = s.sp.mass[1], reach = 0.5 * (s.sp.sigma[0] + s.sp.sigma[1]);
  Vec<D> up = Vec<D>::Zero(), along = Vec<D>::Zero(), side = Vec<D>::Zero();
  up[kUp<D>] = 20;
  along[0] = 1;
  side[1] = 1;  // perpendicular to the line of centres (2D: y; 3D: y, gravity is off anyway)
  s.x[0] = up - (0.5 * reach + 0.001) * along;
  s.x[1] = up + (0.5 * reach + 0.001) * along;
  const Vec<D> v_rel = v_n * along + v_t * side;  // of 0 relative to 1
  s.v[0] = (m1 / (m0 + m1)) * v_rel;
  s.v[1] = (-m0 / (m0 + m1)) * v_rel;
  ForceField<D> ff(c, h);
  ff.set_gravity(0);
  ff.compute(s);
  const double dt = 2e-6;
  bool touched = false;
  for (int k = 0; k < 2'000'000; ++k) {
    velocity_verlet_step(s, ff, dt);
    const bool touching = (s.x[1] - s.x[0]).norm() < reach;
    if (touched && !touching) break;
    touched = touched || touching;
  }
  EXPECT_TRUE(touched);
  const Vec<D> n = (s.x[0] - s.x[1]).normalized();
  const Vec<D> after = s.v[0] - s.v[1];
  const double an = after.dot(n);
  return {an / v_n, (after - an * n).norm() / std::fabs(v_t)};  // approached at -v_n along n
}

TEST(AuthorsModel, HeadOnCollisionLosesNoEnergyToTangentialOnlyFriction) {
  // the text's friction acts on the full relative velocity and damps a head-on collision ...
  const Collision full = collide<2>(1e4, 10.0, std::nullopt, std::nullopt, 0.5, 1e-9);
  EXPECT_LT(full.e_normal, 0.9);
  // ... the authors' tangential-only friction leaves it elastic (the harmonic contact alone)
  const Collision tangential = collide<2>(1e4, 10.0, 0.0, 10.0, 0.5, 1e-9);
  EXPECT_NEAR(tangential.e_normal, 1.0, 1e-6);
  const Collision tangential3 = collide<3>(1e4, 10.0, 0.0, 10.0, 0.5, 1e-9);
  EXPECT_NEAR(tangential3.e_normal, 1.0, 1e-6);
}

TEST(AuthorsModel, ObliqueCollisionLosesOnlyItsTangentialPart) {
  // With tangential-only friction mu_t the normal motion is the undamped harmonic contact
  // (duration t_c = pi sqrt(m_r / k), k = E_sp / sigma_mn^2) and the tangential relative
  // velocity decays as exp(-mu_t t_c / m_r) while the particles touch. The normal turns by
  // ~v_t t_c / sigma_mn ~ 1e-3 rad, which moves ~(v_t / v_n) of that, ~2e-4, of the energy
  // between the two parts: the analytic answer holds to that.
  const double E = 1e4, mu_t = 5.0, v_n = 0.2, v_t = 0.05;
  const Species sp = Species::bidisperse(2, 1.4);
  const double m_r = sp.mass[0] * sp.mass[1] / (sp.mass[0] + sp.mass[1]);
  const double sig = 0.5 * (sp.sigma[0] + sp.sigma[1]);
  const double t_c = units::pi * std::sqrt(m_r / (E / (sig * sig)));
  const Collision c = collide<2>(E, mu_t, 0.0, mu_t, v_n, v_t);
  EXPECT_NEAR(c.e_normal, 1.0, 5e-4) << "the normal part keeps its energy";
  EXPECT_NEAR(c.tangential, std::exp(-mu_t * t_c / m_r), 2e-3) << "t_c = " << t_c;
  EXPECT_LT(c.tangential, 0.9) << "and the tangential part does lose energy";
}

// --- drag as a rate times the mass ---------------------------------------------------------------

template <int D>
void check_same_terminal_time(double zeta, double rate, bool expect_same) {
  SimConfig c = small_config(D, 2, 1.0, zeta, 0.0);
  c.W = 60;
  c.drag_rate = rate;
  c.resolve_and_validate();
  const Hopper<D> h = hopper_for<D>(c);
  ParticleState<D> s = testing::small_and_large<D>(c);
  Vec<D> a = Vec<D>::Zero(), b = Vec<D>::Zero();
  a[kUp<D>] = 20;
  b[kUp<D>] = 20;
  a[0] = -10;
  b[0] = 10;
  s.x[0] = a;
  s.x[1] = b;
  s.v[0] = Vec<D>::Zero();
  s.v[1] = Vec<D>::Zero();
  s.v[0][0] = 1.0;
  s.v[1][0] = 1.0;
  ForceField<D> ff(c, h);
  ff.set_gravity(0);
  ff.compute(s);
  const double dt = 1e-4, T = 1.0;
  for (int k = 0; k < static_cast<int>(T / dt + 0.5); ++k) velocity_verlet_step(s, ff, dt);
  // (the integrator's predicted velocity makes the decay exact to O(dt): 2e-4 relative here)
  if (expect_same) {
    // F = -b M v: every particle decays as exp(-b t), the same terminal-velocity time 1/b
    EXPECT_NEAR(s.v[0][0], s.v[1][0], 1e-14) << "light and heavy particles must decay alike";
    EXPECT_NEAR(s.v[0][0] / std::exp(-rate * T), 1.0, 5e-4);
  } else {
    // F = -zeta v: the light particle slows faster (time M/zeta)
    EXPECT_NEAR(s.v[0][0] / std::exp(-zeta / s.mass(0) * T), 1.0, 5e-4);
    EXPECT_NEAR(s.v[1][0] / std::exp(-zeta / s.mass(1) * T), 1.0, 5e-4);
    EXPECT_LT(s.v[0][0], s.v[1][0] - 0.05);
  }
}

TEST(AuthorsModel, MassProportionalDragGivesEveryParticleTheSameTerminalTime) {
  check_same_terminal_time<2>(0.0, 1.96, true);
  check_same_terminal_time<3>(0.0, 1.96, true);
  check_same_terminal_time<2>(0.5, 0.0, false);
}

TEST(AuthorsModel, MassProportionalDragActsPerVertexOnDpPolygons) {
  for (const char* model : {"dp_smooth", "dp_rough"}) {
    SimConfig c = dp_config(model, 2, 0.0, 0.0);
    c.drag_rate = 2.0;
    c.resolve_and_validate();
    DpFixture fx(c, {{-2.0, 3.0}, {2.0, 3.0}}, 0.0, 3);
    for (auto& v : fx.verts.v) v = Vec<2>(1.0, 0.0);
    const Hopper<2> h = make_hopper<2>(fx.c);
    DpForceField ff(fx.c, h, fx.poly, fx.shape, fx.c.dp.E_c);
    VecArray<2> f(fx.verts.size(), Vec<2>::Zero());
    Drag<2>* drag = nullptr;
    for (ForceTerm<2>* t : ff.terms())
      if (t->name() == "drag") drag = static_cast<Drag<2>*>(t);
    ASSERT_NE(drag, nullptr);
    const TermOutput out = drag->accumulate(fx.verts, f);
    for (int i = 0; i < fx.verts.size(); ++i)
      EXPECT_NEAR(f[i][0] / fx.verts.mass(i), -2.0, 1e-12) << model << " vertex " << i;
    EXPECT_LT(out.power, 0);
  }
}

// --- the smooth contact width and the time step ----------------------------------------------------

TEST(AuthorsModel, SmoothContactWidthSetsTheEdgeWidthAndTheTimeStep) {
  SimConfig text = dp_config("dp_smooth", 4);
  SimConfig authors = text;
  authors.dp.contact_width = 0.2;
  authors.dp.E_c = 1e2;
  authors.E_w = 1e2;  // the wall holds a vertex within delta/2: it is the stiffest term in both
  authors.resolve_and_validate();
  const DpShape a = DpShape::from_config(authors), t = DpShape::from_config(text);
  EXPECT_DOUBLE_EQ(a.delta[0], 0.2 * a.l0[0]);
  EXPECT_DOUBLE_EQ(t.delta[1], 0.1 * t.l0[1]);
  // T ~ delta sqrt(m / E): twice the width and 1/100 of the stiffness give 20 times the period
  const TimeStepChoice ta = choose_time_step(authors), tt = choose_time_step(text);
  EXPECT_EQ(ta.period_term, tt.period_term);
  EXPECT_NEAR(ta.period_min / tt.period_min, 20.0, 1e-9);
}

TEST(AuthorsModel, NewParametersAreCheckedAndOnlyWhereTheyApply) {
  using nlohmann::json;
  const json base = {{"w", 6}, {"zeta", 0.0}, {"mu", 8.5}};
  auto error_field = [](json j) -> std::string {
    try {
      (void)SimConfig::from_json(j);
    } catch (const ConfigError& e) {
      return e.field();
    }
    return "(accepted)";
  };
  json j = base;
  j["mu_n"] = -1;
  EXPECT_EQ(error_field(j), "mu_n");
  j = base;
  j["drag_rate"] = -0.1;
  EXPECT_EQ(error_field(j), "drag_rate");
  j = base;
  j["drag_rate"] = "fast";
  EXPECT_EQ(error_field(j), "drag_rate");
  j = base;
  j["model"] = "dp_rough";
  j["dp"] = {{"contact_width", 0.2}};
  EXPECT_EQ(error_field(j), "dp.contact_width") << "the rough model's disks are l0 wide";
  j["model"] = "dp_smooth";
  EXPECT_EQ(error_field(j), "(accepted)");
  j["dp"] = {{"contact_width", 0}};
  EXPECT_EQ(error_field(j), "dp.contact_width");
  j = base;
  j["sp_contact_law"] = "spring";
  EXPECT_EQ(error_field(j), "sp_contact_law");
  j["model"] = "dp_smooth";
  j["sp_contact_law"] = "force";
  EXPECT_EQ(error_field(j), "sp_contact_law") << "an SP option";
  // defaults leave the canonical job as it was before these parameters existed
  const SimConfig c = SimConfig::from_json(base);
  EXPECT_FALSE(c.to_json().contains("drag_rate"));
  EXPECT_FALSE(c.to_json().contains("mu_n"));
  json authors = base;
  authors["mu_n"] = 0;
  authors["drag_rate"] = 1.96;
  const SimConfig a = SimConfig::from_json(authors);
  EXPECT_EQ(a.to_json()["mu_n"], 0.0);
  EXPECT_EQ(a.to_json()["drag_rate"], 1.96);
  EXPECT_NE(a.effective_seed(), c.effective_seed());
}

}  // namespace
}  // namespace beverloo
