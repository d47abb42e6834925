#include "pile_finder.h"

namespace beverloo {

template <int D>
void PileFinder<D>::find(const ParticleState<D>& s, NeighborList<D>& list, const Hopper<D>& hopper,
                         std::vector<std::uint8_t>& in_pile) {
  const int n = s.size();
  parent_.resize(n);
  for (int i = 0; i < n; ++i) parent_[i] = i;
  // the touching pairs, through the list's pair runs (one flat pass; row by row, every short
  // row's end was a mispredicted branch). The components do not depend on the order of unions.
  list.update_block_lists(s.species.data());
  double sig2[4];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double sig = 0.5 * (s.sp.sigma[a] + s.sp.sigma[b]);
      sig2[2 * a + b] = sig * sig;
    }
  const int* I = list.pair_i();
  const int* J = list.pair_j();
  const std::uint8_t* T = list.pair_type();
  for (int q = 0, end = list.pairs_begin(list.blocks()); q < end; ++q) {
    const int i = I[q], j = J[q];
    if ((s.x[i] - s.x[j]).squaredNorm() >= sig2[T[q]] || s.exited[i] || s.exited[j]) continue;
    const int a = root(i), b = root(j);
    if (a != b) parent_[a < b ? b : a] = a < b ? a : b;  // smaller index as root: deterministic
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
