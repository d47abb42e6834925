#pragma once
/// \file pile_finder.h
/// \brief Which particles belong to the pile: the clusters of overlapping particles that are
/// connected, contact by contact, to the hopper's floor (the funnel walls in 2D, the base in 3D).
///
/// Reinjection must touch "one of the topmost particles" of the pile. Neither "the highest
/// particle" nor "a particle with contacts" will do: with drag only, reinjected particles fall
/// at their terminal velocity, small and large ones collide in the air, and an airborne
/// cluster would become the top that the next reinjection builds on, a tower that never
/// lands (seen at w = 10). Connectivity to the floor excludes everything in the air.
#include <cstdint>
#include <vector>

#include "../geometry/hopper.h"
#include "../neighbor/neighbor_list.h"
#include "../state.h"

namespace beverloo {

template <int D>
class PileFinder {
 public:
  explicit PileFinder(int n) {
    parent_.reserve(n);
    floor_root_.reserve(n);
  }
  /// in_pile[i] = 1 for non-exited particles connected to the floor. The list must be valid
  /// for the current positions (then the answer does not depend on when it was built).
  /// (The list's pair runs are brought up to date: update_block_lists.)
  void find(const ParticleState<D>& s, NeighborList<D>& list, const Hopper<D>& hopper,
            std::vector<std::uint8_t>& in_pile);

 private:
  int root(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  std::vector<int> parent_;
  std::vector<std::uint8_t> floor_root_;
};

}  // namespace beverloo
