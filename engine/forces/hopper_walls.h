#pragma once
/// \file hopper_walls.h
/// \brief Harmonic walls: U = (E_w/2)(1 - 2 d_w/sigma_m)^2 for d_w < sigma_m/2, where d_w is the
/// distance to the nearest point of a wall (so wall ends at the orifice act as corners). DP
/// funnel walls may have a thickness (FunnelCores): then d_w = |r - core| - T/2, negative inside
/// the wall, below the core line the slab's distance, and the same form (its force keeps growing
/// inside).
#include "../geometry/funnel_cores.h"
#include "../geometry/hopper.h"
#include "../neighbor/neighbor_list.h"
#include "force_term.h"
#include "harmonic_overlap.h"

#include <array>
#include <cmath>

namespace beverloo {

template <int D>
class HopperWalls final : public ForceTerm<D> {
 public:
  HopperWalls(const Hopper<D>& hopper, const NeighborList<D>& list, double E_w)
      : hopper_(hopper), list_(list), eps_(E_w) {}
  /// Walls felt at the contact diameters of the two species instead of the state's sigma
  /// (DP vertices: the list's reach is wider than a vertex's contact diameter).
  HopperWalls(const Hopper<D>& hopper, const NeighborList<D>& list, double E_w, std::array<double, 2> diameters)
      : hopper_(hopper), list_(list), eps_(E_w), diameters_(diameters), own_diameters_(true) {}
  std::string_view name() const override { return "hopper_walls"; }
  /// Funnel walls with a thickness (2D DP); nullptr or thickness 0: walls are lines. The cores
  /// must outlive the term, and the list's wall reach must cover them (DpForceField).
  void set_funnel_cores(const FunnelCores* cores) { cores_ = cores && cores->half_thickness() > 0 ? cores : nullptr; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    double energy = 0;
    const int n = s.size();
    for (int i = 0; i < n; ++i) energy += add_to(s, i, f[i]);
    return {energy, 0};
  }
  /// The walls' force on item i added to fi; returns its energy (the fused SP pass calls this).
  double add_to(const ParticleState<D>& s, int i, Vec<D>& fi) const {
    std::uint8_t mask = list_.wall_mask(i);
    if (!mask) return 0;
    double energy = 0;
    const double half = 0.5 * (own_diameters_ ? diameters_[s.species[i]] : s.sigma(i)), inv_half = 1.0 / half;
    for (int w = 0; mask; ++w, mask >>= 1) {
      if (!(mask & 1u)) continue;
      if constexpr (D == 2) {
        // thick walls: the funnel cores; beside a side wall (above its start) a half-space;
        // below a side wall's start its end point, as a line wall (the code below)
        if (cores_ && (w < 2 || s.x[i][1] > hopper_.wall_start(w)[1])) {
          energy += w < 2 ? add_thick(s.x[i], w, half, inv_half, fi) : add_side(s.x[i], w, half, inv_half, fi);
          continue;
        }
      }
      const Vec<D> away = s.x[i] - hopper_.nearest_point(w, s.x[i]);
      const double d2 = away.squaredNorm();
      if (d2 >= half * half || d2 == 0) continue;
      const double d = std::sqrt(d2);
      double dU_dd;
      energy += HarmonicOverlap::energy(eps_, d, inv_half, dU_dd);
      fi += (-dU_dd / d) * away;
    }
    return energy;
  }

 private:
  /// Funnel wall k of thickness T against a vertex of reach `half` at x: d = |x - core| - T/2
  /// (the capsule), or below the core line within its span the slab's distance (FunnelCores).
  double add_thick(const Vec<D>& x, int k, double half, double inv_half, Vec<D>& fi) const {
    double dU_dd;
    if (cores_->in_slab_region(k, x)) {
      Vec<D> gradient;
      const double d = cores_->slab_distance(k, x, gradient);
      if (d >= half) return 0;
      const double energy = HarmonicOverlap::energy(eps_, d, inv_half, dU_dd);
      fi += -dU_dd * gradient;
      return energy;
    }
    const Vec<D> away = x - cores_->nearest_point(k, x);
    const double r2 = away.squaredNorm(), reach = half + cores_->half_thickness();
    if (r2 >= reach * reach || r2 == 0) return 0;
    const double r = std::sqrt(r2);
    const double energy = HarmonicOverlap::energy(eps_, r - cores_->half_thickness(), inv_half, dU_dd);
    fi += (-dU_dd / r) * away;
    return energy;
  }

  /// Side wall k (2 or 3) of walls with a thickness, beside it (above its start): a half-space,
  /// d the signed distance (negative beyond it: the force keeps growing). The container's
  /// outside is wall; nothing of a flow belongs there.
  double add_side(const Vec<D>& x, int k, double half, double inv_half, Vec<D>& fi) const {
    const Vec<D> a = hopper_.wall_start(k);
    const double inward = k == 2 ? 1.0 : -1.0;  // the left side wall's inside is +x
    const double d = (x[0] - a[0]) * inward;
    if (d >= half) return 0;
    double dU_dd;
    const double energy = HarmonicOverlap::energy(eps_, d, inv_half, dU_dd);
    fi[0] += -dU_dd * inward;
    return energy;
  }

  const Hopper<D>& hopper_;
  const NeighborList<D>& list_;
  double eps_;
  std::array<double, 2> diameters_{};
  bool own_diameters_ = false;
  const FunnelCores* cores_ = nullptr;
};

}  // namespace beverloo
