#pragma once
/// \file sp_contact.h
/// \brief Soft-particle contacts: harmonic repulsion U = (E_sp/2)(1 - r/sigma_mn)^2 and kinetic
/// friction on overlapping pairs (full or split along the centre line, kinetic_friction.h),
/// evaluated in one pass over the Verlet list.
///
/// Why one pass: friction acts exactly on the pairs that overlap, so both parts share the
/// distance test; a second loop over the list would double the memory traffic of the hottest
/// loop. The parts stay separately testable: with v = 0 only the repulsion acts, and
/// friction_forces() gives the friction alone.
#include <cmath>
#include <cstdint>
#include <vector>

#include "../neighbor/neighbor_list.h"
#include "force_term.h"
#include "kinetic_friction.h"

namespace beverloo {

template <int D>
class SpContact final : public ForceTerm<D> {
 public:
  /// scale_with_sigma: the pair's energy scale is E_sp sigma_mn (sp_contact_law "force")
  SpContact(const NeighborList<D>& list, double E_sp, FrictionLaw friction, bool scale_with_sigma = false)
      : list_(list), eps_(E_sp), law_(friction), scale_with_sigma_(scale_with_sigma) {}
  std::string_view name() const override { return "sp_contact"; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    if (!friction_on_ || !law_.active()) return loop<Friction::None>(s, f);
    return law_.split() ? loop<Friction::Split>(s, f) : loop<Friction::Full>(s, f);
  }
  /// Friction force on each particle alone (for the |F^mu| observable); overwrites out.
  void friction_forces(const ParticleState<D>& s, VecArray<D>& out) const;
  void set_friction_enabled(bool on) { friction_on_ = on; }
  /// Pairs of one group (vertices of one rough polygon in self-contact) repel but do not rub:
  /// kinetic friction acts between particles (physics.md 4). nullptr: every pair rubs.
  void set_friction_groups(const std::vector<int>* group) { friction_group_ = group; }
  /// Largest relative overlap 1 - r/sigma_mn seen in the last accumulate().
  double max_overlap() const { return max_overlap_; }
  const FrictionLaw& friction() const { return law_; }

 private:
  enum class Friction { None, Full, Split };
  template <Friction kFriction>
  TermOutput loop(const ParticleState<D>& s, VecArray<D>& f);
  /// The friction force on i from j (dx = x_i - x_j, r = |dx|); kSplit: the split law.
  template <bool kSplit>
  Vec<D> friction_on(const ParticleState<D>& s, int i, int j, const Vec<D>& dx, double r) const {
    if constexpr (kSplit) return kinetic_friction_force<D>(law_, s.v[i], s.v[j], Vec<D>(dx / r));
    return kinetic_friction_force<D>(law_.mu_t, s.v[i], s.v[j]);
  }

  const NeighborList<D>& list_;
  double eps_;
  FrictionLaw law_;
  bool scale_with_sigma_;
  bool friction_on_ = true;
  const std::vector<int>* friction_group_ = nullptr;
  bool rubs(int i, int j) const { return !friction_group_ || (*friction_group_)[i] != (*friction_group_)[j]; }
  double max_overlap_ = 0;
};

template <int D>
template <typename SpContact<D>::Friction kFriction>
TermOutput SpContact<D>::loop(const ParticleState<D>& s, VecArray<D>& f) {
  // species-pair tables: contact distance^2, its inverse, the energy scale over it
  double sig2[2][2], inv_sig[2][2], eps[2][2], k[2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double sig = 0.5 * (s.sp.sigma[a] + s.sp.sigma[b]);
      sig2[a][b] = sig * sig;
      inv_sig[a][b] = 1.0 / sig;
      eps[a][b] = scale_with_sigma_ ? eps_ * sig : eps_;
      k[a][b] = eps[a][b] * inv_sig[a][b];
    }
  // Plain component arithmetic on the arrays' doubles (a Vec<D> is D packed doubles): the
  // compiler keeps i's sums in registers, where Eigen temporaries taken by reference were
  // spilled to the stack and reloaded with a store-forwarding stall per pair.
  const double* X = s.x.data()->data();
  const double* V = s.v.data()->data();
  double* F = f.data()->data();
  const std::uint8_t* species = s.species.data();
  const double mu_n = law_.mu_n, mu_t = law_.mu_t;
  double energy = 0, power = 0, max_ov = 0;
  const int n = s.size();
  for (int i = 0; i < n; ++i) {
    double xi[D], vi[D], fi[D];
    for (int d = 0; d < D; ++d) {
      xi[d] = X[i * D + d];
      vi[d] = V[i * D + d];
      fi[d] = 0;
    }
    const int si = species[i];
    for (const int* p = list_.row_begin(i), *end = list_.row_end(i); p != end; ++p) {
      const int j = *p;
      double dx[D], r2 = 0;
      for (int d = 0; d < D; ++d) {
        dx[d] = xi[d] - X[j * D + d];
        r2 += dx[d] * dx[d];
      }
      const int sj = species[j];
      if (r2 >= sig2[si][sj]) continue;
      const double r = std::sqrt(r2);
      // HarmonicOverlap, written out: U = (eps/2) ov^2, ov = 1 - r/sigma, |F| = eps ov / sigma
      const double ov = 1.0 - r * inv_sig[si][sj];
      energy += 0.5 * eps[si][sj] * ov * ov;
      max_ov = ov > max_ov ? ov : max_ov;
      const double scale = k[si][sj] * ov / r;
      double fij[D];  // on i, along x_i - x_j (repulsive), plus friction
      for (int d = 0; d < D; ++d) fij[d] = scale * dx[d];
      if constexpr (kFriction != Friction::None) {
        if (rubs(i, j)) {
          double dv[D];
          for (int d = 0; d < D; ++d) dv[d] = vi[d] - V[j * D + d];
          double ff[D];
          if constexpr (kFriction == Friction::Split) {  // kinetic_friction.h, the split law
            const double inv_r = 1.0 / r;
            double dv_dot_n = 0;
            for (int d = 0; d < D; ++d) dv_dot_n += dv[d] * (dx[d] * inv_r);
            for (int d = 0; d < D; ++d) {
              const double dvn = dv_dot_n * (dx[d] * inv_r);
              ff[d] = -mu_n * dvn - mu_t * (dv[d] - dvn);
            }
          } else {
            for (int d = 0; d < D; ++d) ff[d] = -mu_t * dv[d];
          }
          for (int d = 0; d < D; ++d) {
            power += ff[d] * dv[d];
            fij[d] += ff[d];
          }
        }
      }
      for (int d = 0; d < D; ++d) {
        fi[d] += fij[d];
        F[j * D + d] -= fij[d];
      }
    }
    for (int d = 0; d < D; ++d) F[i * D + d] += fi[d];
  }
  max_overlap_ = max_ov;
  return {energy, power};
}

}  // namespace beverloo
