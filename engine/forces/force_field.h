#pragma once
/// \file force_field.h
/// \brief All force terms of one simulation, evaluated together. Owns the Verlet list so that
/// every evaluation starts from a valid list.
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "../config.h"
#include "../integrate/exit_watch.h"
#include "../integrate/sp_sweeps_avx2.h"
#include "drag.h"
#include "gravity.h"
#include "hopper_walls.h"
#include "parallel_chunks.h"
#include "sp_contact.h"

namespace beverloo {

struct ForceReport {
  double U_contact = 0, U_wall = 0, U_gravity = 0;
  double U_shape = 0;  ///< DP shape energy (area, segment length, bending); 0 for SP
  double P_drag = 0, P_friction = 0;
  double max_overlap = 0;  ///< largest relative pair overlap 1 - r/sigma_mn
  double potential() const { return U_contact + U_wall + U_gravity + U_shape; }
};

template <int D>
class ForceField {
 public:
  ForceField(const SimConfig& c, const Hopper<D>& hopper)
      : list_(c.skin),
        contact_(list_, c.E_sp, FrictionLaw{c.mu_normal(), c.mu_tangential()}, normal_law(c.sp_contact_law)),
        walls_(hopper, list_, c.E_w),
        gravity_(c.gravity),
        drag_(drag_coefficients(c.zeta, c.drag_rate, Species::bidisperse(D, c.size_ratio).mass)),
        hopper_(hopper) {
    list_.use_blocks(true);
  }

  /// Zeroes s.f, brings the list up to date and adds every term. O(N).
  ForceReport compute(ParticleState<D>& s) {
    list_.update(s, hopper_);
    return evaluate(s);
  }
  /// compute() with the list as it is (the caller keeps it valid: SpModel::step).
  ForceReport evaluate(ParticleState<D>& s) {
    // Block by block (the list's blocks, neighbor_list.h), on threads_ threads: each block
    // owns its particles' forces. Per particle: gravity and drag (Gravity::add_to and
    // Drag::add_to written out) in a sweep that also clears the old force, the walls, then
    // the pairs. The terms' own accumulate() give the same forces term by term
    // (tests/physics/test_force_field.cpp), and every thread count the same bits.
    contact_.prepare(s);
    const int nb = list_.blocks();
    partial_.resize(nb);
    const double g = gravity_.g();
    const std::array<double, 2> drag = drag_coefficients_now();
    // plain doubles: a component write into an Eigen vector made GCC spill it to the stack and
    // reload it whole, a store-forwarding stall per particle that cost more than the loop
    const double* __restrict X = s.x.data()->data();
    const double* __restrict V = s.v.data()->data();
    double* __restrict F = s.f.data()->data();
    const std::uint8_t* __restrict species = s.species.data();
    const std::array<double, 2> mass = s.sp.mass;
    auto block = [&](int b) {
      // sums in locals, stored once: accumulated in partial_[b] they made a store and reload
      // on every particle's dependency chain
      double U_gravity = 0, P_drag = 0, U_wall = 0;
      const int lo = list_.block_begin(b), hi = list_.block_begin(b + 1);
      for (int i = lo; i < hi; ++i) {
        const int sp = species[i];
        const double m = mass[sp], c = drag[sp];
        double v2 = 0;
        for (int d = 0; d < D; ++d) {
          const double vd = V[i * D + d];
          F[i * D + d] = -c * vd;
          v2 += vd * vd;
        }
        F[i * D + kUp<D>] -= m * g;
        U_gravity += m * g * X[i * D + kUp<D>];
        P_drag -= c * v2;
      }
      for (const int *w = list_.wall_items_begin(b), *end = list_.wall_items_end(b); w != end; ++w)
        U_wall += walls_.add_to(s, *w, s.f[*w]);
      BlockPartial& out = partial_[b];
      out.contact = contact_.block(s, s.f, b);
      out.U_gravity = U_gravity;
      out.P_drag = P_drag;
      out.U_wall = U_wall;
    };
    for_each_block(nb, block);
    typename SpContact<D>::BlockSums contact;
    ForceReport r;
    for (const BlockPartial& p : partial_) {  // in block order, whatever the threads
      contact.add(p.contact);
      r.U_wall += p.U_wall;
      r.U_gravity += p.U_gravity;
      r.P_drag += p.P_drag;
    }
    const TermOutput c = contact_.finish(contact);
    r.U_contact = c.energy;
    r.P_friction = c.power;
    r.max_overlap = contact_.max_overlap();
    return r;
  }
  /// What a step needs of its forces (forces_and_kick()): the energies are diagnostics that
  /// compute() and evaluate() give.
  struct StepForces {
    double max_overlap = 0;  ///< largest relative pair overlap 1 - r/sigma_mn
    bool finite = true;      ///< every position and velocity finite after the kick
  };

  /// The first of a step's two sweeps over the items (SpModel::step): the drift of
  /// velocity_verlet.h (x += v dt + a dt^2/2, v += a dt/2, a = f/m), whether an item moved far
  /// enough from the list's reference positions for a rebuild (returned; true if the list has
  /// none), whether
  /// an item is where the exit bookkeeping has work (exits_possible, see ExitWatch), and the
  /// start of the new force: f = gravity + drag at (x(t+dt), v~), as evaluate() starts it.
  /// One pass instead of three (drift, exit test, force start); the same operations on each
  /// item, so the same bits. Between this and forces_and_kick(), an item given a new position
  /// and velocity needs start_force_of().
  bool drift_and_start_forces(ParticleState<D>& s, double dt, const ExitWatch& watch, bool& exits_possible) {
    const int n = s.size();
    DriftConstants k;
    k.dt = dt;
    k.half_dt = 0.5 * dt;
    k.half_dt2 = 0.5 * dt * dt;
    const VecArray<D>& reference = list_.reference_positions();
    k.reference = static_cast<int>(reference.size()) == n ? reference.data()->data() : nullptr;
    k.limit2 = list_.rebuild_distance2();
    k.watch = watch;
    k.set_force_start(gravity_.g(), drag_coefficients_now(), s.sp.mass);
    double* X = s.x.data()->data();
    double* V = s.v.data()->data();
    double* F = s.f.data()->data();
    int moved = 0, exiting = 0;
    if (threads_ == 1) {  // no parallel region: even a team of one cost ~2 % of a step in libgomp
      moved = step_drift_range<D>(0, n, X, V, F, s.inv_mass.data(), s.species.data(), s.exited.data(), k, exiting);
    } else {
      // one chunk per thread (a chunk's constants are its own copies, see drift_range)
#pragma omp parallel for schedule(static) reduction(| : moved, exiting) num_threads(threads_)
      for (int c = 0; c < threads_; ++c)
        moved |= step_drift_range<D>(int(long(n) * c / threads_), int(long(n) * (c + 1) / threads_), X, V, F,
                                s.inv_mass.data(), s.species.data(), s.exited.data(), k, exiting);
    }
    exits_possible = exiting != 0;
    return moved != 0 || !k.reference;
  }
  /// Item i's force start (gravity and drag), after the protocol placed it anew.
  void start_force_of(ParticleState<D>& s, int i) {
    const int sp = s.species[i];
    start_force<D>(i, s.v.data()->data(), s.f.data()->data(), drag_coefficients_now()[sp], s.sp.mass[sp] * gravity_.g());
  }
  /// The second sweep: the walls and the pairs added to the started forces (the list as it
  /// is), then the kick v += f dt / (2m) of velocity_verlet.h, each block's items once the
  /// block's forces are complete (SpContact::block_and_kick), the list's late items after
  /// every block.
  /// The forces and velocities are evaluate()'s and kick()'s bits, for every thread count.
  StepForces forces_and_kick(ParticleState<D>& s, double dt) {
    contact_.prepare(s);
    const int nb = list_.blocks();
    partial_.resize(nb);
    const typename SpContact<D>::Kick k{0.5 * dt, s.v.data()->data(), s.inv_mass.data(), list_.late_kick()};
    auto block = [&](int b) {
      for (const int *i = list_.wall_items_begin(b), *end = list_.wall_items_end(b); i != end; ++i)
        walls_.add_to(s, *i, s.f[*i]);
      partial_[b].contact = contact_.block_and_kick(s, s.f, b, k);
    };
    for_each_block(nb, block);
    typename SpContact<D>::BlockSums contact;
    for (const BlockPartial& p : partial_) contact.add(p.contact);
    const double* X = s.x.data()->data();
    const double* F = s.f.data()->data();
    double* V = s.v.data()->data();
    bool bad = contact.nonfinite;
    for (int i : list_.late_kick_items()) bad = not_finite(kick_one<D>(i, X, V, F, k.half_dt, k.inv_mass)) || bad;
    return {contact.max_overlap, !bad};
  }
  /// Dissipation off: FIRE minimises the potential energy only.
  void set_dissipation(bool on) {
    contact_.set_friction_enabled(on);
    drag_.set_enabled(on);
  }
  void set_gravity(double g) { gravity_.set_g(g); }
  /// Threads for evaluate() (1: none); results are the same bits for every count.
  void set_threads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  int threads() const { return threads_; }
  NeighborList<D>& list() { return list_; }
  const NeighborList<D>& list() const { return list_; }
  const SpContact<D>& contact() const { return contact_; }
  /// The terms one by one (for the generic physics tests).
  std::vector<ForceTerm<D>*> terms() { return {&contact_, &walls_, &gravity_, &drag_}; }

 private:
  /// block(b) for every block b < nb on threads_ threads (parallel_chunks.h).
  template <class Block>
  void for_each_block(int nb, Block& block) const {
    for_each_chunk(threads_, nb, block);
  }
  /// The drag coefficient of each species, 0 while dissipation is off.
  std::array<double, 2> drag_coefficients_now() const {
    return drag_.active() ? drag_.coefficients() : std::array<double, 2>{0, 0};
  }
  NeighborList<D> list_;
  SpContact<D> contact_;
  HopperWalls<D> walls_;
  Gravity<D> gravity_;
  Drag<D> drag_;
  const Hopper<D>& hopper_;
  int threads_ = 1;
  struct BlockPartial {
    typename SpContact<D>::BlockSums contact;
    double U_wall = 0, U_gravity = 0, P_drag = 0;
  };
  std::vector<BlockPartial> partial_;  ///< one per block, kept between evaluations
};

}  // namespace beverloo
