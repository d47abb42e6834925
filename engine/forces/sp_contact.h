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
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override;
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

}  // namespace beverloo
