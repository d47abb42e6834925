#pragma once
/// \file reinjector.h
/// \brief Puts an exited particle back on top of the pile (physics.md 6.4): touching one of the
/// topmost particles (centre distance exactly sigma_mn), overlapping no other particle and no
/// wall, with the velocity of the particle it touches. N stays fixed.
///
/// The particle to touch is drawn from the pile (see pile_finder.h) within `top_band` of the
/// pile's highest particle, the direction uniformly from the upper half circle (2D) or hemisphere (3D). If
/// `max_attempts` draws all collide, the particle is dropped just above the pile instead
/// (counted as a fallback, so that a run can report how often that happened).
#include <cstdint>
#include <functional>
#include <vector>

#include "../config.h"
#include "../geometry/hopper.h"
#include "../neighbor/neighbor_list.h"
#include "../rng.h"
#include "../state.h"

namespace beverloo {

template <int D>
class Reinjector {
 public:
  Reinjector(const Hopper<D>& hopper, const ReinjectionParams& p, int n) : hopper_(hopper), p_(p) {
    candidates_.reserve(n);
  }
  /// Places particle i; returns false if the fallback placement was used.
  /// in_pile: membership of the pile (PileFinder), kept up to date for placed particles.
  /// near: a list valid for s's positions, to find the particles near a tried spot (null: test
  /// all N); the same placements either way.
  bool reinject(ParticleState<D>& s, int i, Rng& rng, const std::vector<std::uint8_t>& in_pile,
                const NeighborList<D>* near = nullptr);
  /// The authors' rule (reinjection.rule "lanes", 2D): particle i goes to lane
  /// `placement % lanes(s)` (lanes at 0, -2, +2, -4, +4, ... small diameters from the axis,
  /// taken in turn), one small diameter above the top of the highest particle within 1.5 small
  /// diameters of the lane, lifted if that spot is not free (returns false then). Its downward
  /// velocity is that of the nearest particle below it in the lane, reduced by free fall over
  /// 1.5 small diameters when its drag rate is below 0.098/t0; its sideways velocity 0.1 of
  /// that, alternating in sign with the particle index. No random numbers are drawn.
  /// drag_rate: the particle's drag coefficient over its mass (1/t0).
  bool reinject_in_lane(ParticleState<D>& s, int i, std::int64_t placement, double drag_rate,
                        const NeighborList<D>* near = nullptr);
  /// Number of lanes: floor(W / 2 small diameters) - 2, at least 1.
  int lanes(const ParticleState<D>& s) const;
  /// True if particle i at position p overlaps no other particle and no wall. near: as in
  /// reinject(); the answer does not depend on it.
  bool is_free(const ParticleState<D>& s, int i, const Vec<D>& p, int touching,
               const NeighborList<D>* near = nullptr) const;
  /// A further test of a spot that the body disks find free (DP: the polygons' own edges,
  /// which a stretched soft polygon pushes beyond its body disk). Empty: none.
  void set_extra_test(std::function<bool(int, const Vec<D>&)> test) { extra_test_ = std::move(test); }

 private:
  const Hopper<D>& hopper_;
  ReinjectionParams p_;
  std::vector<int> candidates_;
  std::function<bool(int, const Vec<D>&)> extra_test_;
};

}  // namespace beverloo
