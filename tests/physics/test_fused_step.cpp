// The SP model's step (SpModel::step) runs two fused sweeps over the particles
// (ForceField::drift_and_start_forces, forces_and_kick): it must give the very bits of the
// plain step built from its parts (drift, the rebuild with its sort, the protocol's hook,
// evaluate, kick), also while particles exit and are reinjected, with one force block and with
// two; and its exit watch must never hide work from the exit bookkeeping.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/integrate/velocity_verlet.h"
#include "engine/models/sp_model.h"
#include "engine/protocol/exit_counter.h"
#include "engine/protocol/hopper_run.h"

namespace beverloo {
namespace {

/// Counts exits as HopperRun does and puts each particle that has dropped deep enough back at
/// the top of the pile (a fixed spot per reinjection), telling the list and the model.
template <int D>
class ReinjectingHook final : public StepHook<D> {
 public:
  ReinjectingHook(const Hopper<D>& h, int n, double top, HopperModel<D>* model)
      : hopper_(h), exits_(h, 1.0, n), top_(top), model_(model) {}
  void between_drift_and_force(ParticleState<D>& s, NeighborList<D>& list, bool exits_possible) override {
    exits_.update(s, 0.0, rec_);
    // the watch may call for the sweep when it finds nothing, never skip it when it would
    if (!exits_possible) {
      EXPECT_TRUE(exits_.to_reinject().empty());
      EXPECT_EQ(counted_, rec_.exit_time.size()) << "the drift's exit watch missed an exit";
    }
    counted_ = rec_.exit_time.size();
    for (int i : exits_.to_reinject()) {
      s.x[i] = Vec<D>::Zero();
      s.x[i][kUp<D>] = top_ + 1.5 * (reinjected_ % 8);
      s.x[i][0] = hopper_.lateral_centre() + 1.2 * ((reinjected_ % 5) - 2);
      s.v[i] = Vec<D>::Zero();
      s.exited[i] = 0;
      ++reinjected_;
      list.relocate(i, s, hopper_);
      if (model_) model_->reinjected(i, s, rng_);
    }
  }
  ExitWatch exit_watch(const Species& sp) const override { return exits_.watch(sp); }
  int reinjected() const { return reinjected_; }

 private:
  const Hopper<D>& hopper_;
  ExitCounter<D> exits_;
  FlowRecord rec_;
  std::size_t counted_ = 0;
  double top_;
  HopperModel<D>* model_;
  Rng rng_{1};
  int reinjected_ = 0;
};

template <int D>
bool same_bits(const VecArray<D>& a, const VecArray<D>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(Vec<D>) * a.size()) == 0;
}

/// A flowing pile of n particles (HopperRun, `warm` steps), then `steps` steps by SpModel::step
/// and by the plain step side by side, compared bit for bit after every step.
template <int D>
void check_fused_step(int n, double zeta, double mu, std::int64_t warm, std::int64_t steps, double mu_n = -1) {
  SimConfig c;
  c.dimension = D;
  c.N = n;
  c.W = D == 2 ? (n > 1000 ? 30 : 16) : 10;
  c.w = 5;
  c.zeta = zeta;
  c.mu = mu;
  if (mu_n >= 0) c.mu_n = mu_n;  // the split friction law
  c.seed = 7;
  c.resolve_and_validate();
  HopperRun<D> run(c, RunOptions{});
  run.prepare();
  run.advance(warm);
  const Hopper<D>& h = run.hopper();
  const double dt = run.time_step().dt;
  double top = 0;
  for (const Vec<D>& x : run.state().x) top = std::max(top, x[kUp<D>]);

  ParticleState<D> fused = run.state(), plain = run.state();
  SpModel<D> model(c, h);
  model.start_flow(fused);  // step > 0: the forces of the state are kept
  ForceField<D> ff(c, h);
  // the plain step's pairs two at a time, the model's four at a time where AVX2 is (else both
  // two): the step's run against evaluate()'s
  const_cast<SpContact<D>&>(ff.contact()).set_simd_width(2);
  ff.set_gravity(c.gravity);
  ff.set_dissipation(true);
  ff.list().invalidate();
  ParticleState<D> scratch;
  ReinjectingHook<D> fused_hook(h, n, top, &model), plain_hook(h, n, top, nullptr);
  for (std::int64_t k = 0; k < steps; ++k) {
    model.step(fused, dt, fused_hook);
    NeighborList<D>& list = ff.list();
    const double moved2 = drift(plain, dt, list.reference_positions());
    if (list.due(moved2)) list.build_sorting(plain, h, scratch);
    plain_hook.between_drift_and_force(plain, list, true);
    if (list.forced()) list.build_sorting(plain, h, scratch);
    ff.evaluate(plain);
    kick(plain, dt);
    ++plain.step;
    ASSERT_TRUE(same_bits<D>(fused.x, plain.x) && same_bits<D>(fused.v, plain.v) && same_bits<D>(fused.f, plain.f))
        << "the fused step differs from the plain one at step " << k;
    ASSERT_EQ(fused.id, plain.id);
  }
  EXPECT_GT(fused_hook.reinjected(), 0) << "no particle was reinjected: the test missed that path";
  EXPECT_EQ(fused_hook.reinjected(), plain_hook.reinjected());
}

TEST(FusedStep, EqualsThePlainStepOneBlockDragAndFriction2D) { check_fused_step<2>(300, 0.3, 2.0, 6000, 4000); }
TEST(FusedStep, EqualsThePlainStepTwoBlocksFriction2D) { check_fused_step<2>(1200, 0.0, 3.0, 6000, 3000); }
TEST(FusedStep, EqualsThePlainStepTwoBlocksDrag2D) { check_fused_step<2>(1200, 0.3, 0.0, 6000, 3000); }
TEST(FusedStep, EqualsThePlainStepTwoBlocksFriction3D) { check_fused_step<3>(1200, 0.0, 3.0, 3000, 1500); }
TEST(FusedStep, EqualsThePlainStepSplitFriction3D) { check_fused_step<3>(500, 0.0, 3.0, 3000, 2000, 1.0); }
TEST(FusedStep, EqualsThePlainStepDrag3D) { check_fused_step<3>(500, 0.5, 0.0, 3000, 2000); }

}  // namespace
}  // namespace beverloo
