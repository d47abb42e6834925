// The generic physics checks over the model seam (engine/models/hopper_model.h): for every
// model the engine has, every force term it registers is checked through the one interface,
// in a settled, contact-rich hopper state: conservative terms against the finite-difference
// gradient of their energy, dissipative ones for the sign of their power. A registered term
// that the state gives nothing to check (no energy, no power) fails the test: every term must
// be covered, so a new term cannot slip in untested.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dp_support.h"
#include "engine/protocol/hopper_run.h"
#include "support.h"

namespace beverloo {
namespace {

struct ModelCase {
  const char* name;
  SimConfig config;
  double settle_time;  ///< t0 of flow before the check: a pile with contacts and wall contacts
};

std::vector<ModelCase> every_model() {
  SimConfig sp2 = testing::small_config(2, 80, 3.0, 0.5, 0.5);
  SimConfig sp3 = testing::small_config(3, 150, 2.5, 0.5, 0.5);
  SimConfig smooth = testing::dp_config("dp_smooth", 14, 0.5, 0.5);
  SimConfig rough = testing::dp_config("dp_rough", 14, 0.5, 0.5);
  for (SimConfig* c : {&smooth, &rough}) {
    c->dp.K_b = 0.1;  // a bending term with energy to check
    c->resolve_and_validate();
  }
  return {{"sp 2D", sp2, 2.0}, {"sp 3D", sp3, 2.0}, {"dp_smooth", smooth, 1.0}, {"dp_rough", rough, 1.0}};
}

/// Terms that no hopper state exercises (a polygon folding through itself), each with the
/// dedicated test that covers it. A term neither checked here nor listed fails.
const std::map<std::string, std::string> kCoveredByDedicatedTests = {
    {"dp_rough_fold_barrier", "DpForces.RoughPolygonFoldedAtAVertexMeetsTheFoldBarrier"},
    {"dp_rough_edge_core", "DpForces.RoughEdgeCoreHoldsVerticesOutOfStretchedEdges"},
};

/// Makes the settled state contact-rich for every term, the same way for every model: every
/// body is moved 20 % of the way towards the axis and the floor, its points (particle or
/// vertices) with it, shapes unchanged (overlaps, floor and wall contacts); then the
/// even-numbered point nearest the right orifice corner and the next one are put astride that
/// corner, just under it (for polygons, whose vertices come in even runs, an edge under it).
template <int D>
void squeeze(HopperModel<D>& model, const ParticleState<D>& bodies, ParticleState<D>& s, double orifice_half_width) {
  Vec<D> corner = Vec<D>::Zero();
  corner[0] = orifice_half_width;
  int nearest = 0;
  for (int i = 0; i < s.size(); ++i) {
    Vec<D> b = bodies.x[model.body_of(i)];
    b[kUp<D>] = std::max(0.0, b[kUp<D>]);
    s.x[i] -= 0.2 * b;
    s.x[i][kUp<D>] -= 0.02 * s.sigma(i);
    if (i % 2 == 0 && i + 1 < s.size() && (s.x[i] - corner).squaredNorm() < (s.x[nearest] - corner).squaredNorm())
      nearest = i;
  }
  const double r = 0.5 * s.sigma(nearest);
  for (int k = 0; k < 2; ++k) {
    Vec<D> off = Vec<D>::Zero();
    off[0] = (k ? 0.25 : -0.25) * r;
    off[kUp<D>] = -0.05 * r;
    s.x[nearest + k] = corner + off;
  }
}

template <int D>
void check_every_term(const ModelCase& mc) {
  HopperRun<D> run(mc.config, RunOptions{});
  run.prepare();
  run.advance(std::llround(mc.settle_time / run.time_step().dt));
  HopperModel<D>& model = run.model();
  ParticleState<D>& live = model.term_state(run.state());
  squeeze(model, run.state(), live, run.hopper().orifice_half_width());
  model.compute_forces(run.state());
  std::set<std::string> uncovered;
  for (ForceTerm<D>* term : model.terms()) {
    const std::string name(term->name());
    // conservative part, at rest: forces = -grad U (the lists stay valid: moves of 1e-6)
    ParticleState<D> s = live;
    for (auto& v : s.v) v.setZero();
    VecArray<D> f(s.size(), Vec<D>::Zero());
    const double energy = term->accumulate(s, f).energy;
    const double eps = 1e-7;
    auto energy_at = [&](ParticleState<D>& t) {
      VecArray<D> g(t.size(), Vec<D>::Zero());
      return term->accumulate(t, g).energy;
    };
    double worst = 0;
    for (int i = 0; i < s.size(); ++i)
      for (int d = 0; d < D; ++d) {
        const double keep = s.x[i][d];
        s.x[i][d] = keep + eps;
        const double up = energy_at(s);
        s.x[i][d] = keep - eps;
        const double down = energy_at(s);
        s.x[i][d] = keep;
        const double numeric = -(up - down) / (2 * eps);
        worst = std::max(worst, std::fabs(f[i][d] - numeric) / std::max(1.0, std::fabs(f[i][d])));
      }
    EXPECT_LT(worst, 1e-4) << mc.name << ": " << name << " forces differ from -grad U";
    // dissipative part, in motion: never adds energy
    ParticleState<D> m = live;
    testing::random_velocities(m, 5, 1.0);
    VecArray<D> fm(m.size(), Vec<D>::Zero());
    const double power = term->accumulate(m, fm).power;
    EXPECT_LE(power, 1e-12) << mc.name << ": " << name << " adds energy";
    if (energy == 0 && power == 0 && !kCoveredByDedicatedTests.count(name)) uncovered.insert(name);
  }
  EXPECT_TRUE(uncovered.empty()) << mc.name << ": terms with nothing to check in a settled hopper (no energy, no power): "
                                 << [&] {
                                      std::string all;
                                      for (const auto& n : uncovered) all += " " + n;
                                      return all;
                                    }();
}

TEST(ModelTerms, EveryTermOfEveryModelIsCheckedThroughTheModelInterface) {
  for (const ModelCase& mc : every_model()) {
    SCOPED_TRACE(mc.name);
    if (mc.config.dimension == 2)
      check_every_term<2>(mc);
    else
      check_every_term<3>(mc);
  }
}

TEST(ModelTerms, TheSpForceFieldIsNotBuiltForDpRuns) {
  HopperRun<2> dp(testing::dp_config("dp_smooth", 6), RunOptions{});
  EXPECT_NE(dp.dp(), nullptr);
  EXPECT_THROW((void)dp.forces(), std::logic_error);
  HopperRun<2> sp(testing::small_config(2, 20, 3.0), RunOptions{});
  EXPECT_EQ(sp.dp(), nullptr);
  EXPECT_NO_THROW((void)sp.forces());
}

}  // namespace
}  // namespace beverloo
