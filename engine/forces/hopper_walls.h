#pragma once
/// \file hopper_walls.h
/// \brief Harmonic walls: U = (E_w/2)(1 - 2 d_w/sigma_m)^2 for d_w < sigma_m/2, where d_w is the
/// distance to the nearest point of a wall (so wall ends at the orifice act as corners).
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
  const Hopper<D>& hopper_;
  const NeighborList<D>& list_;
  double eps_;
  std::array<double, 2> diameters_{};
  bool own_diameters_ = false;
};

}  // namespace beverloo
