#include "pile_finder.h"

namespace beverloo {

template <int D>
void PileFinder<D>::find(const ParticleState<D>& s, const NeighborList<D>& list, const Hopper<D>& hopper,
                         std::vector<std::uint8_t>& in_pile) {
  const int n = s.size();
  parent_.resize(n);
  for (int i = 0; i < n; ++i) parent_[i] = i;
  for (int i = 0; i < n; ++i) {
    if (s.exited[i]) continue;
    for (const int* p = list.row_begin(i), *end = list.row_end(i); p != end; ++p) {
      const int j = *p;
      if (s.exited[j]) continue;
      const double sig = 0.5 * (s.sigma(i) + s.sigma(j));
      if ((s.x[i] - s.x[j]).squaredNorm() >= sig * sig) continue;
      const int a = root(i), b = root(j);
      if (a != b) parent_[a < b ? b : a] = a < b ? a : b;  // smaller index as root: deterministic
    }
  }
  floor_root_.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    if (s.exited[i]) continue;
    const double r = 0.5 * s.sigma(i);
    // a wall the particle touches is in its wall mask (the list is valid): the exact test only there
    const std::uint8_t near = list.wall_mask(i);
    for (int w = 0; w < Hopper<D>::kNumWalls; ++w)
      if (Hopper<D>::is_floor(w) && (near >> w & 1u) &&
          (s.x[i] - hopper.nearest_point(w, s.x[i])).squaredNorm() < r * r)
        floor_root_[root(i)] = 1;
  }
  in_pile.assign(n, 0);
  for (int i = 0; i < n; ++i) in_pile[i] = !s.exited[i] && floor_root_[root(i)];
}

template class PileFinder<2>;
template class PileFinder<3>;

}  // namespace beverloo
