#pragma once
/// \file sp_contact.h
/// \brief Soft-particle contacts: a normal law's repulsion (contact_laws.h: the harmonic
/// U = (eps/2)(1 - r/sigma_mn)^2 of the paper, Hertz, ...) and kinetic friction on overlapping
/// pairs (full or split along the centre line, kinetic_friction.h), evaluated in one pass over
/// the Verlet list, block by block (neighbor_list.h: blocks; each block adds only to its own
/// items' forces, so blocks can run on threads). The pair loops are written once, over the
/// normal law as a type; the law's registry row hands this term the loops made for it
/// (SpContactLoops), so a law is chosen once per block, never per pair.
///
/// Why one pass: friction acts exactly on the pairs that overlap, so both parts share the
/// distance test; a second loop over the list would double the memory traffic of the hottest
/// loop. The parts stay separately testable: with v = 0 only the repulsion acts, and
/// friction_forces() gives the friction alone.
#include <cmath>
#include <cstdint>
#include <vector>

#include "../integrate/sp_sweeps_avx2.h"
#include "../neighbor/neighbor_list.h"
#include "contact_laws.h"
#include "force_term.h"
#include "harmonic_overlap.h"
#include "kinetic_friction.h"
#include "sp_pairs_avx2.h"
#include "sp_pairs_sse2.h"

namespace beverloo {

template <int D>
class SpContact final : public ForceTerm<D> {
 public:
  /// normal: the normal law's registry row (contact_laws.h; the pair's energy scale from E_sp)
  SpContact(NeighborList<D>& list, double E_sp, FrictionLaw friction, const NormalLawRow& normal = normal_law("energy"))
      : list_(list), eps_(E_sp), law_(friction), normal_(&normal), loops_(&normal.loops<D>()) {
    set_simd_width(simd_width_);
  }
  std::string_view name() const override { return "sp_contact"; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    prepare(s);
    BlockSums total;
    for (int b = 0; b < list_.blocks(); ++b) total.add(block(s, f, b));
    return finish(total);
  }
  /// What one block of the list adds up besides forces; added in block order (never in the
  /// order threads finish), so that the totals too are the same for every thread count.
  struct BlockSums {
    double energy = 0, power = 0, max_overlap = 0;
    bool nonfinite = false;  ///< block_and_kick(): a kicked item's position or velocity is not finite
    void add(const BlockSums& o) {
      energy += o.energy;
      power += o.power;
      max_overlap = o.max_overlap > max_overlap ? o.max_overlap : max_overlap;
      nonfinite = nonfinite || o.nonfinite;
    }
  };
  /// What the step's force pass needs to kick each block's items once their forces are complete
  /// (ForceField::forces_and_kick): v += (half_dt / m) f, the operations of kick().
  struct Kick {
    double half_dt = 0;
    double* V = nullptr;  ///< the state's velocities, written
    const double* inv_mass = nullptr;
    /// NeighborList::late_kick(): items whose velocity another block still reads; the caller
    /// kicks them once every block is done
    const std::uint8_t* late = nullptr;
  };
  /// Before block(): the species tables and the list's incoming lists (serial).
  void prepare(const ParticleState<D>& s);
  /// The pairs of block b of the list: forces on the block's own items only, so blocks can
  /// run on different threads (neighbor_list.h, blocks()).
  BlockSums block(const ParticleState<D>& s, VecArray<D>& f, int b) const { return (this->*loops_->block)(s, f, b); }
  /// block() for a step: the same forces, no energy or power sums (only the largest overlap),
  /// and each of the block's items that is not late kicked once the block's forces are complete,
  /// while the block is still in cache: no separate kick over all items.
  BlockSums block_and_kick(const ParticleState<D>& s, VecArray<D>& f, int b, const Kick& k) const {
    return (this->*loops_->block_and_kick)(s, f, b, k);
  }
  /// block() and block_and_kick() for the normal law Normal (SpContactLoops holds these).
  template <class Normal>
  BlockSums block_as(const ParticleState<D>& s, VecArray<D>& f, int b) const {
    if (!friction_on_ || !law_.active()) return loop<Normal, Friction::None, false>(s, f, b, nullptr);
    return law_.split() ? loop<Normal, Friction::Split, false>(s, f, b, nullptr)
                        : loop<Normal, Friction::Full, false>(s, f, b, nullptr);
  }
  template <class Normal>
  BlockSums block_and_kick_as(const ParticleState<D>& s, VecArray<D>& f, int b, const Kick& k) const {
    if (!friction_on_ || !law_.active()) return loop<Normal, Friction::None, true>(s, f, b, &k);
    return law_.split() ? loop<Normal, Friction::Split, true>(s, f, b, &k) : loop<Normal, Friction::Full, true>(s, f, b, &k);
  }
  TermOutput finish(const BlockSums& total) {
    max_overlap_ = total.max_overlap;
    return {total.energy, total.power};
  }
  /// Friction force on each particle alone (for the |F^mu| observable); overwrites out.
  void friction_forces(const ParticleState<D>& s, VecArray<D>& out) const;
  void set_friction_enabled(bool on) { friction_on_ = on; }
  /// The 2D pair runs four pairs at a time (AVX2, where the processor has it: the default),
  /// two (SSE2) or one by one (1): the same forces, for the tests. Returns the width set (4
  /// without AVX2 sets 2; a normal law without a lane form always runs one by one).
  int set_simd_width(int width) {
    simd_width_ = !normal_->lanes ? 1 : width >= 4 && avx2::available() ? 4 : (width >= 2 ? 2 : 1);
    return simd_width_;
  }
  void set_simd(bool on) { set_simd_width(on ? 4 : 1); }
  int simd_width() const { return simd_width_; }
  /// Pairs of one group (vertices of one rough polygon in self-contact) repel but do not rub:
  /// kinetic friction acts between particles (physics.md 4). nullptr: every pair rubs.
  void set_friction_groups(const std::vector<int>* group) { friction_group_ = group; }
  /// Largest relative overlap 1 - r/sigma_mn seen in the last accumulate().
  double max_overlap() const { return max_overlap_; }
  const FrictionLaw& friction() const { return law_; }
  const NormalLawRow& normal_law_row() const { return *normal_; }

 private:
  enum class Friction { None, Full, Split };
  /// kKick: block_and_kick() (k its kick), else block() (k null).
  template <class Normal, Friction kFriction, bool kKick>
  BlockSums loop(const ParticleState<D>& s, VecArray<D>& f, int b, const Kick* k) const;
  /// Block b's pair run (NeighborList::pairs_begin): each pair's force added to i, and
  /// subtracted from j if j is this block's (else j's block adds it: incoming()). The pairs
  /// only: loop() adds the incoming pairs and kicks.
  template <class Normal, Friction kFriction, bool kKick>
  BlockSums pairs(const ParticleState<D>& s, VecArray<D>& f, int b, int hi) const;
  /// 2D: block b's pair run two pairs at a time (sp_pairs_sse2.h), the same forces bit for
  /// bit; the pairs only (loop() adds the incoming pairs and kicks). The lanes are the lane
  /// form of HarmonicOverlap, the one law that has one so far.
  template <Friction kFriction, bool kKick>
  BlockSums pairs_sse2(const ParticleState<D>& s, VecArray<D>& f, int b, int hi) const;
#if defined(__SSE2__)
  /// The SIMD runs' species-pair tables (sp_pairs_sse2.h) from this term's.
  sse2::PairTables lane_tables() const {
    sse2::PairTables t;
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c) {
        t.sig2[2 * a + c] = sig2_[a][c];
        t.inv_sig[2 * a + c] = inv_sig_[a][c];
        t.half_eps[2 * a + c] = 0.5 * eps_ab_[a][c];
        t.eps[2 * a + c] = eps_ab_[a][c];
      }
    t.make_lanes();
    return t;
  }
  template <Friction kFriction>
  static constexpr sse2::Friction lane_friction() {
    return kFriction == Friction::None   ? sse2::Friction::None
           : kFriction == Friction::Full ? sse2::Friction::Full
                                         : sse2::Friction::Split;
  }
#endif
  /// The pairs of block b with items of earlier blocks, from the block's side (forces only).
  template <class Normal, Friction kFriction>
  void incoming(const ParticleState<D>& s, VecArray<D>& f, int b) const;
  /// The force on i from j (dx = x_i - x_j, r2 = |dx|^2 < sigma_ij^2) into fij; the energy and
  /// friction power of the pair into sums. Exactly antisymmetric: from j's side (dx and the
  /// velocities negated) every operation gives the negated value, so a pair evaluated by two
  /// blocks adds opposite forces.
  template <class Normal, Friction kFriction>
  [[gnu::always_inline]] inline void pair_force(const double* vi, const double* vj, const double* dx, double r2, int si,
                                                int sj, bool rub, double* fij, double& energy, double& power,
                                                double& max_overlap) const;
  /// Listed pair (i, j) seen from i (xi: i's position, si its species): if the two touch, the
  /// force on i into fij, energy and power into the sums, and true. The one scalar pair of the
  /// rows, the incoming lists and the SSE2 rows' odd pair.
  template <class Normal, Friction kFriction>
  [[gnu::always_inline]] inline bool touching_pair(const double* X, const double* V, const std::uint8_t* species, int i,
                                                   const double* xi, int si, int j, double* fij, double& energy,
                                                   double& power, double& max_overlap) const {
    double dx[D], r2 = 0;
    for (int d = 0; d < D; ++d) {
      dx[d] = xi[d] - X[j * D + d];
      r2 += dx[d] * dx[d];
    }
    const int sj = species[j];
    if (r2 >= sig2_[si][sj]) return false;
    pair_force<Normal, kFriction>(V + i * D, V + j * D, dx, r2, si, sj, rubs(i, j), fij, energy, power, max_overlap);
    return true;
  }
  /// Pair (i, j) of a block's pair run, one at a time: if the two touch, the force added to i
  /// and subtracted from j if j < hi (else j's block adds it: incoming()). The scalar pairs()
  /// and the SSE2 run's odd pair.
  template <class Normal, Friction kFriction>
  [[gnu::always_inline]] inline void run_pair(const double* X, const double* V, double* F, const std::uint8_t* species,
                                              int i, int j, int hi, double& energy, double& power,
                                              double& max_overlap) const {
    double fij[D];
    if (!touching_pair<Normal, kFriction>(X, V, species, i, X + i * D, species[i], j, fij, energy, power, max_overlap)) return;
    for (int d = 0; d < D; ++d) F[i * D + d] += fij[d];
    if (j < hi)
      for (int d = 0; d < D; ++d) F[j * D + d] -= fij[d];
  }
  /// The friction force on i from j (dx = x_i - x_j, r = |dx|); kSplit: the split law.
  template <bool kSplit>
  Vec<D> friction_on(const ParticleState<D>& s, int i, int j, const Vec<D>& dx, double r) const {
    if constexpr (kSplit) return kinetic_friction_force<D>(law_, s.v[i], s.v[j], Vec<D>(dx / r));
    return kinetic_friction_force<D>(law_.mu_t, s.v[i], s.v[j]);
  }

  NeighborList<D>& list_;  ///< not const: prepare() brings its incoming lists up to date
  double eps_;
  FrictionLaw law_;
  const NormalLawRow* normal_;
  const SpContactLoops<D>* loops_;  ///< the pair loops of the normal law
  bool friction_on_ = true;
  int simd_width_ = avx2::available() ? 4 : 2;  ///< pairs per step of the 2D runs (the 3D step's: 4 or 1)
  const std::vector<int>* friction_group_ = nullptr;
  bool rubs(int i, int j) const { return !friction_group_ || (*friction_group_)[i] != (*friction_group_)[j]; }
  /// Whether friction acts on every pair in contact, as the SIMD pair runs assume: no friction
  /// groups, or no friction at all (the rough DP disks of a drag-only job)
  template <Friction kFriction>
  bool rubs_everywhere() const { return !friction_group_ || kFriction == Friction::None; }
  double max_overlap_ = 0;
  // species-pair tables (prepare()): contact distance^2, its inverse, the energy scale
  double sig2_[2][2], inv_sig_[2][2], eps_ab_[2][2];
};

/// The pair loops of one normal law (contact_laws.h), as its registry row hands them out.
template <int D>
struct SpContactLoops {
  typename SpContact<D>::BlockSums (SpContact<D>::*block)(const ParticleState<D>&, VecArray<D>&, int) const;
  typename SpContact<D>::BlockSums (SpContact<D>::*block_and_kick)(const ParticleState<D>&, VecArray<D>&, int,
                                                                    const typename SpContact<D>::Kick&) const;
  template <class Normal>
  static const SpContactLoops& of() {
    static const SpContactLoops loops{&SpContact<D>::template block_as<Normal>,
                                      &SpContact<D>::template block_and_kick_as<Normal>};
    return loops;
  }
};

template <int D>
template <class Normal, typename SpContact<D>::Friction kFriction>
[[gnu::always_inline]] inline void SpContact<D>::pair_force(const double* vi, const double* vj, const double* dx,
                                                            double r2, int si, int sj, bool rub, double* fij,
                                                            double& energy, double& power, double& max_overlap) const {
  const double r = std::sqrt(r2);
  double ov;
  // |F| / r: (eps ov / sigma) / r for the harmonic law, in the lane forms' order
  const double scale = Normal::force(eps_ab_[si][sj], inv_sig_[si][sj], r, energy, ov) / r;
  max_overlap = ov > max_overlap ? ov : max_overlap;
  for (int d = 0; d < D; ++d) fij[d] = scale * dx[d];  // on i, along x_i - x_j (repulsive)
  if constexpr (kFriction != Friction::None) {
    if (rub) {
      double dv[D], ff[D];
      for (int d = 0; d < D; ++d) dv[d] = vi[d] - vj[d];
      if constexpr (kFriction == Friction::Split) {  // kinetic_friction.h, the split law
        const double inv_r = 1.0 / r;
        double dv_dot_n = 0;
        for (int d = 0; d < D; ++d) dv_dot_n += dv[d] * (dx[d] * inv_r);
        for (int d = 0; d < D; ++d) {
          const double dvn = dv_dot_n * (dx[d] * inv_r);
          ff[d] = -law_.mu_n * dvn - law_.mu_t * (dv[d] - dvn);
        }
      } else {
        for (int d = 0; d < D; ++d) ff[d] = -law_.mu_t * dv[d];
      }
      for (int d = 0; d < D; ++d) {
        power += ff[d] * dv[d];
        fij[d] += ff[d];
      }
    }
  }
}

template <int D>
template <class Normal, typename SpContact<D>::Friction kFriction, bool kKick>
typename SpContact<D>::BlockSums SpContact<D>::loop(const ParticleState<D>& s, VecArray<D>& f, int b,
                                                    const Kick* k) const {
  const int lo = list_.block_begin(b), hi = list_.block_begin(b + 1);
  BlockSums sums = [&] {
#if defined(__SSE2__)
    if constexpr (D == 2 && Normal::kLanes)
      if (rubs_everywhere<kFriction>() && simd_width_ >= 2) return pairs_sse2<kFriction, kKick>(s, f, b, hi);
#endif
    return pairs<Normal, kFriction, kKick>(s, f, b, hi);
  }();
  if (lo > 0) incoming<Normal, kFriction>(s, f, b);
  if constexpr (kKick) {  // every force of the block is complete
    const double* X = s.x.data()->data();
    const double* F = f.data()->data();
    sums.nonfinite = step_kick_range<D>(lo, hi, X, k->V, F, k->half_dt, k->inv_mass, k->late);
  }
  return sums;
}

template <int D>
template <class Normal, typename SpContact<D>::Friction kFriction, bool kKick>
typename SpContact<D>::BlockSums SpContact<D>::pairs(const ParticleState<D>& s, VecArray<D>& f, int b, int hi) const {
  // Plain component arithmetic on the arrays' doubles (a Vec<D> is D packed doubles): where
  // Eigen temporaries were taken by reference, GCC spilled them to the stack and reloaded them
  // with a store-forwarding stall per pair.
  const double* X = s.x.data()->data();
  const double* V = s.v.data()->data();
  double* F = f.data()->data();
  const std::uint8_t* species = s.species.data();
  const int* I = list_.pair_i();
  const int* J = list_.pair_j();
  // the sums in locals (registers): accumulated into the returned struct they lived in memory,
  // a store and reload on every pair's dependency chain
  double energy = 0, power = 0, max_ov = 0;
  int q = list_.pairs_begin(b);
  const int q_end = list_.pairs_begin(b + 1);
#if defined(BEVERLOO_HAVE_AVX2_PAIRS)
  // 3D, a step: four pairs at a time where the processor has AVX2 (the same bits; no sums needed)
  if constexpr (D == 3 && kKick && Normal::kLanes)
    if (simd_width_ == 4 && rubs_everywhere<kFriction>())
      q = avx2::four_pairs_run_3d<lane_friction<kFriction>()>(X, V, F, I, J, list_.pair_type(), q, q_end,
                                                              static_cast<std::size_t>(hi), lane_tables(), law_.mu_n,
                                                              law_.mu_t, max_ov);
#endif
  for (; q < q_end; ++q) run_pair<Normal, kFriction>(X, V, F, species, I[q], J[q], hi, energy, power, max_ov);
  BlockSums sums;
  if constexpr (!kKick) {  // else unused: the compiler drops their arithmetic
    sums.energy = energy;
    sums.power = power;
  }
  sums.max_overlap = max_ov;
  return sums;
}

template <int D>
template <class Normal, typename SpContact<D>::Friction kFriction>
void SpContact<D>::incoming(const ParticleState<D>& s, VecArray<D>& f, int b) const {
  const double* X = s.x.data()->data();
  const double* V = s.v.data()->data();
  double* F = f.data()->data();
  const std::uint8_t* species = s.species.data();
  // pairs with items of earlier blocks, seen from this block's side (energy and power were
  // counted by the earlier block: into a sink here)
  double sink_energy = 0, sink_power = 0, sink_max = 0;
  for (const int *q = list_.receivers_begin(b), *q_end = list_.receivers_end(b); q != q_end; ++q) {
    const int j = *q;
    double xj[D], fj[D];
    for (int d = 0; d < D; ++d) {
      xj[d] = X[j * D + d];
      fj[d] = 0;
    }
    const int sj = species[j];
    for (const int *p = list_.incoming_begin(j), *end = list_.incoming_end(j); p != end; ++p) {
      double fji[D];
      if (!touching_pair<Normal, kFriction>(X, V, species, j, xj, sj, *p, fji, sink_energy, sink_power, sink_max)) continue;
      for (int d = 0; d < D; ++d) fj[d] += fji[d];
    }
    for (int d = 0; d < D; ++d) F[j * D + d] += fj[d];
  }
}

#if defined(__SSE2__)
template <int D>
template <typename SpContact<D>::Friction kFriction, bool kKick>
typename SpContact<D>::BlockSums SpContact<D>::pairs_sse2(const ParticleState<D>& s, VecArray<D>& f, int b,
                                                          int hi) const {
  constexpr auto kLane = lane_friction<kFriction>();
  const sse2::PairTables t = lane_tables();
  const double* X = s.x.data()->data();
  const double* V = s.v.data()->data();
  double* F = f.data()->data();
  const std::uint8_t* species = s.species.data();
  const int* I = list_.pair_i();
  const int* J = list_.pair_j();
  const std::uint8_t* T = list_.pair_type();
  const sse2::FrictionLanes mu(law_.mu_n, law_.mu_t);
  sse2::LaneSums lanes;
  int q = list_.pairs_begin(b);
  const int q_end = list_.pairs_begin(b + 1);
  const auto u = [](int k) { return static_cast<std::size_t>(static_cast<unsigned>(k)); };  // k >= 0
#if defined(BEVERLOO_HAVE_AVX2_PAIRS)
  if (simd_width_ == 4)
    q = avx2::four_pairs_run<kLane, !kKick>(X, V, F, I, J, T, q, q_end, u(hi), t, law_.mu_n, law_.mu_t, lanes);
#endif
  for (; q_end - q >= 2; q += 2)
    sse2::two_pairs<kLane, !kKick>(X, V, F, u(I[q]), u(J[q]), u(I[q + 1]), u(J[q + 1]), T[q], T[q + 1], u(hi), t, mu,
                                   lanes);
  double energy = 0, power = 0, max_ov = 0;
  // the last, odd pair: the scalar code, after the others as in pairs()
  if (q != q_end) run_pair<HarmonicOverlap, kFriction>(X, V, F, species, I[q], J[q], hi, energy, power, max_ov);
  BlockSums sums;
  if constexpr (!kKick) {
    sums.energy = energy + sse2::sum_lanes(lanes.energy);
    sums.power = power + sse2::sum_lanes(lanes.power);
  }
  const double lane_max = sse2::max_lanes(lanes.max_ov);
  sums.max_overlap = max_ov > lane_max ? max_ov : lane_max;
  return sums;
}
#endif

}  // namespace beverloo
