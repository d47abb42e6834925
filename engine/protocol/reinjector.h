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
#include <functional>
#include <vector>

#include "../config.h"
#include "../geometry/hopper.h"
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
  bool reinject(ParticleState<D>& s, int i, Rng& rng, const std::vector<std::uint8_t>& in_pile);
  /// True if particle i at position p overlaps no other particle and no wall.
  bool is_free(const ParticleState<D>& s, int i, const Vec<D>& p, int touching) const;
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
