#include "neighbor_list.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace beverloo {

template <int D>
bool NeighborList<D>::moved_beyond_half_skin(const ParticleState<D>& s) const {
  const double limit2 = 0.25 * skin_ * skin_;
  const int n = s.size();
  for (int i = 0; i < n; ++i)
    if ((s.x[i] - x_ref_[i]).squaredNorm() > limit2) return true;
  return false;
}

template <int D>
void NeighborList<D>::bin(const ParticleState<D>& s) {
  const int n = s.size();
  // Bounding box and grid; a cell is at least the largest list cutoff wide.
  Vec<D> lo = Vec<D>::Constant(INFINITY), hi = Vec<D>::Constant(-INFINITY);
  for (int i = 0; i < n; ++i) {
    lo = lo.cwiseMin(s.x[i]);
    hi = hi.cwiseMax(s.x[i]);
  }
  double max_extra = 0;
  if (extra_)
    for (int i = 0; i < n; ++i) max_extra = std::max(max_extra, (*extra_)[i]);
  double cell = std::max(s.sp.sigma[0], s.sp.sigma[1]) + max_extra + skin_;
  long total = 1;
  dims_ = {1, 1, 1};
  for (;;) {  // a blown-up particle far away must not make the grid huge: coarsen instead
    total = 1;
    for (int d = 0; d < D; ++d) {
      dims_[d] = std::max(1, static_cast<int>((hi[d] - lo[d]) / cell) + 1);
      total *= dims_[d];
    }
    if (total <= 4L * n + 64) break;
    cell *= 1.5;
  }
  const double inv_cell = 1.0 / cell;
  grid_lo_ = lo;
  cell_width_ = cell;
  cell_of_.resize(n);
  cell_start_.assign(total + 1, 0);
  for (int i = 0; i < n; ++i) {
    int c = 0;
    for (int d = D - 1; d >= 0; --d) {
      int k = static_cast<int>((s.x[i][d] - lo[d]) * inv_cell);
      k = std::min(k, dims_[d] - 1);
      c = c * dims_[d] + k;
    }
    cell_of_[i] = c;
    ++cell_start_[c + 1];
  }
  for (long c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
}

template <int D>
void NeighborList<D>::update_block_lists(const std::uint8_t* species) {
  if (!block_lists_stale_) return;
  block_lists_stale_ = false;
  const int n = static_cast<int>(row_end_.size());
  const int nb = blocks();
  in_items_.clear();
  receivers_.clear();
  receivers_start_.assign(nb + 1, 0);
  late_.assign(n, 0);
  late_items_.clear();
  wall_items_.clear();
  wall_start_.assign(nb + 1, 0);
  for (int b = 0; b < nb; ++b) {
    for (int i = block_begin(b), hi = block_begin(b + 1); i < hi; ++i)
      if (wall_mask_[i]) wall_items_.push_back(i);
    wall_start_[b + 1] = static_cast<int>(wall_items_.size());
  }
  if (!run_fresh_) make_pair_runs(species);
  const int* __restrict PI = pair_i_.data();
  const int* __restrict PJ = pair_j_.data();
  if (nb == 1) return;
  // incoming lists: a counting pass, then a fill, over the pairs that cross a block boundary
  // (pairs in increasing i, so each incoming list is increasing)
  in_start_.assign(n + 2, 0);
  for (int b = 0; b < nb; ++b) {
    const int hi = block_begin(b + 1);
    for (int k = pair_start_[b]; k < pair_start_[b + 1]; ++k)
      if (PJ[k] >= hi) ++in_start_[PJ[k] + 2];
  }
  for (int j = 0; j < n; ++j) in_start_[j + 2] += in_start_[j + 1];
  in_items_.resize(in_start_[n + 1]);
  for (int b = 0; b < nb; ++b) {
    const int hi = block_begin(b + 1);
    for (int k = pair_start_[b]; k < pair_start_[b + 1]; ++k)
      if (PJ[k] >= hi) {
        in_items_[in_start_[PJ[k] + 1]++] = PI[k];
        // late kicks: the receiver (its velocity is read by the sender's row) and the sender
        // (read by the receiver's incoming list)
        late_[PI[k]] = 1;
        late_[PJ[k]] = 1;
      }
  }
  for (int b = 0; b < nb; ++b) {
    for (int j = block_begin(b), hi = block_begin(b + 1); j < hi; ++j)
      if (in_start_[j + 1] > in_start_[j]) receivers_.push_back(j);
    receivers_start_[b + 1] = static_cast<int>(receivers_.size());
  }
  for (int i = 0; i < n; ++i)
    if (late_[i]) late_items_.push_back(i);
}

template <int D>
void NeighborList<D>::make_pair_runs(const std::uint8_t* species) {
  // One flat pass over every slot of the rows (an unused slot holds -1), kept without a
  // branch: a loop per row paid a mispredicted branch at nearly every row's end. After a build
  // by build_sorting() the runs are written by the build itself; this pass is for the rows
  // that relocate() changed (a reinjection) and for the other builds.
  index_slots();
  const int n = static_cast<int>(row_end_.size());
  const int nb = blocks();
  const int slots = row_start_[n];
  pair_i_.resize(slots);
  pair_j_.resize(slots);
  pair_type_.resize(slots);
  pair_start_.assign(nb + 1, 0);
  const int* __restrict nbr = nbr_.data();
  const int* __restrict row = slot_row_.data();
  int* __restrict PI = pair_i_.data();
  int* __restrict PJ = pair_j_.data();
  std::uint8_t* __restrict PT = pair_type_.data();
  int q = 0;
  for (int b = 0; b < nb; ++b) {
    for (int k = row_start_[block_begin(b)], end = row_start_[block_begin(b + 1)]; k < end; ++k) {
      const int j = nbr[k];
      PI[q] = row[k];
      PJ[q] = j;
      PT[q] = static_cast<std::uint8_t>(2 * species[row[k]] + species[j < 0 ? 0 : j]);  // an unused slot: overwritten
      q += j >= 0;
    }
    pair_start_[b + 1] = q;
  }
}

template <int D>
void NeighborList<D>::index_slots() {
  if (slots_indexed_) return;
  slots_indexed_ = true;
  const int n = static_cast<int>(row_end_.size());
  slot_row_.resize(row_start_[n]);
  for (int i = 0; i < n; ++i) std::fill(slot_row_.begin() + row_start_[i], slot_row_.begin() + row_start_[i + 1], i);
}

template <int D>
void NeighborList<D>::start_build(const ParticleState<D>& s) {
  block_lists_stale_ = true;
  force_ = false;
  ++builds_;
  run_fresh_ = false;
  grid_ = true;
  relocated_.clear();
  relocated_.reserve(s.size());
  x_ref_.assign(s.x.begin(), s.x.end());
  const int n = s.size();
  row_start_.resize(n + 1);
  row_end_.resize(n);
  nbr_.clear();
  wall_mask_.resize(n);
}

template <int D>
std::uint8_t NeighborList<D>::walls_in_reach(const Vec<D>& x, double reach, const Hopper<D>& hopper) const {
  std::uint8_t mask = walls_beyond_ ? walls_beyond_(x, reach) : 0;
  for (int w = 0; w < Hopper<D>::kNumWalls; ++w)
    if (!hopper.beyond(w, x, reach) && (x - hopper.nearest_point(w, x)).squaredNorm() < reach * reach)
      mask |= std::uint8_t(1u << w);
  return mask;
}

template <int D>
void NeighborList<D>::build(const ParticleState<D>& s, const Hopper<D>& hopper) {
  const int n = s.size();
  start_build(s);
  bin(s);
  grid_sorted_ = false;
  cell_items_.resize(n);
  // fill in index order so that each cell lists its particles in increasing index
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i) cell_items_[cursor_[cell_of_[i]]++] = i;
  // The candidates' data in cell order, so that the scans read memory in sequence (through
  // cell_items_ every candidate was a load from anywhere in the arrays)
  cell_x_.resize(n);
  cell_species_.resize(n);
  cell_extra_.resize(extra_ ? n : 0);
  cell_group_.resize(group_ ? n : 0);
  for (int k = 0; k < n; ++k) {
    const int j = cell_items_[k];
    cell_x_[k] = s.x[j];
    cell_species_[k] = s.species[j];
    if (extra_) cell_extra_[k] = (*extra_)[j];
    if (group_) cell_group_[k] = (*group_)[j];
  }
  if (extra_) {
    if (group_)
      build_rows<true, true>(s, hopper);
    else
      build_rows<true, false>(s, hopper);
  } else if (group_) {
    build_rows<false, true>(s, hopper);
  } else {
    build_rows<false, false>(s, hopper);
  }
  slots_indexed_ = false;
}

template <int D>
template <bool kExtra, bool kGroups>
void NeighborList<D>::build_rows(const ParticleState<D>& s, const Hopper<D>& hopper) {
  const int n = s.size();
  const Cutoffs cut2 = cutoffs(s.sp);
  const auto& dims = dims_;
  const Vec<D>* __restrict cx = cell_x_.data();
  const std::uint8_t* __restrict csp = cell_species_.data();
  const double* __restrict cextra = cell_extra_.data();
  const int* __restrict cgroup = cell_group_.data();
  const int* __restrict citem = cell_items_.data();
  std::size_t q = 0;  // the next free slot of nbr_
  for (int i = 0; i < n; ++i) {
    row_start_[i] = static_cast<int>(q);
    const Vec<D> xi = s.x[i];
    const int si = s.species[i];
    const double extra_i = extra(i);
    const int gi = kGroups ? (*group_)[i] : -1;
    // decode cell coordinates of i
    int ci[3] = {0, 0, 0};
    int c = cell_of_[i];
    for (int d = 0; d < D; ++d) {
      ci[d] = c % dims[d];
      c /= dims[d];
    }
    const int lo0 = std::max(ci[0] - 1, 0), hi0 = std::min(ci[0] + 1, dims[0] - 1);
    const int lo1 = std::max(ci[1] - 1, 0), hi1 = std::min(ci[1] + 1, dims[1] - 1);
    const int lo2 = D == 3 ? std::max(ci[2] - 1, 0) : 0, hi2 = D == 3 ? std::min(ci[2] + 1, dims[2] - 1) : 0;
    for (int c2 = lo2; c2 <= hi2; ++c2)
      for (int c1 = lo1; c1 <= hi1; ++c1) {
        // the cells c0 = lo0 .. hi0 of one grid row are contiguous in cell order
        const int first = (c2 * dims[1] + c1) * dims[0];
        const int k0 = cell_start_[first + lo0], k1 = cell_start_[first + hi0 + 1];
        if (nbr_.size() < q + (k1 - k0) + kRowSlack)
          nbr_.resize(std::max<std::size_t>(2 * nbr_.size(), q + (k1 - k0) + kRowSlack + 64));
        int* __restrict out = nbr_.data();
        for (int k = k0; k < k1; ++k) {
          const int j = citem[k];
          const double d2 = (xi - cx[k]).squaredNorm();
          bool listed;
          if constexpr (kExtra) {
            const double cut = 0.5 * (s.sp.sigma[si] + s.sp.sigma[csp[k]]) + std::max(extra_i, cextra[k]) + skin_;
            listed = d2 < cut * cut;
          } else {
            listed = d2 < cut2.c[si][csp[k]];
          }
          listed = listed && j > i;
          if constexpr (kGroups)
            if (cgroup[k] == gi) listed = listed && !excluded(i, j);
          out[q] = j;  // written always, kept if listed: no branch to mispredict
          q += listed;
        }
      }
    std::sort(nbr_.begin() + row_start_[i], nbr_.begin() + q);
    // close the row: its slack (room for relocate(); the resize above left room) and wall mask
    row_end_[i] = static_cast<int>(q);
    std::fill(nbr_.begin() + q, nbr_.begin() + q + kRowSlack, -1);
    q += kRowSlack;
    wall_mask_[i] = walls_in_reach(s.x[i], 0.5 * wall_diameter(s, s.species[i]) + skin_, hopper);
  }
  nbr_.resize(q);
  row_start_[n] = static_cast<int>(q);
}

template <int D>
void NeighborList<D>::build_sorting(ParticleState<D>& s, const Hopper<D>& hopper, ParticleState<D>& scratch) {
  if (group_ || extra_) {  // items tied to others by index (polygons) keep their order
    build(s, hopper);
    return;
  }
  const int n = s.size();
  bin(s);
  // counting sort by cell, stable: slot k of the new order holds old item order_[k]
  order_.resize(n);
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i) order_[cursor_[cell_of_[i]]++] = i;
  s.permute(order_, scratch);
  start_build(s);
  grid_sorted_ = true;

  const Cutoffs cut2 = cutoffs(s.sp);
  // Cell cc now holds the items cell_start_[cc] .. cell_start_[cc + 1] - 1, and every item of a
  // later cell has a higher index: the j > i of row i are the later items of i's own cell and
  // the items of the neighbour cells after it, visited in increasing cell (so index) order.
  const auto& dims = dims_;
  const long plane = long(dims[0]) * dims[1];
  const double* __restrict X = s.x.data()->data();
  const std::uint8_t* __restrict species = s.species.data();
  // Rows are written through a cursor q into nbr_, kept larger than any row can need (every
  // candidate of the row plus its slack), and appended without a branch: a push_back per
  // listed pair tested the capacity and reloaded the arrays through s (it might alias them).
  // The blocks' pair runs (see make_pair_runs) are written alongside, through a cursor p:
  // the rows in order, without their slack.
  nbr_.resize(std::max(nbr_.capacity(), std::size_t(n) * (kRowSlack + 8)));
  const auto room_for_pairs = [&](std::size_t size) {
    pair_i_.resize(size);
    pair_j_.resize(size);
    pair_type_.resize(size);
  };
  room_for_pairs(std::max(pair_i_.capacity(), std::size_t(n) * 8));
  const int nb = blocks();
  pair_start_.assign(nb + 1, 0);
  int next_block = 1, next_block_first = block_begin(1);
  int q = 0, p = 0;
  int cell = 0;
  for (int i = 0; i < n; ++i) {
    while (cell_start_[cell + 1] <= i) ++cell;
    for (; next_block < nb && i == next_block_first; next_block_first = block_begin(++next_block))
      pair_start_[next_block] = p;
    row_start_[i] = q;
    double xi[D];
    for (int d = 0; d < D; ++d) xi[d] = X[i * D + d];
    const double* cut_i = cut2.c[species[i]];
    const int type_i = 2 * species[i];
    // always_inline: GCC stopped inlining this lambda when the TU grew (8 % of case b)
    auto scan = [&](int from, int to) __attribute__((always_inline)) {
      if (static_cast<int>(nbr_.size()) < q + (to - from) + kRowSlack)
        nbr_.resize(std::max<std::size_t>(2 * nbr_.size(), q + (to - from) + kRowSlack + 64));
      if (static_cast<int>(pair_i_.size()) < p + (to - from))
        room_for_pairs(std::max<std::size_t>(2 * pair_i_.size(), p + (to - from) + 64));
      int* __restrict out = nbr_.data();
      int* __restrict PI = pair_i_.data();
      int* __restrict PJ = pair_j_.data();
      std::uint8_t* __restrict PT = pair_type_.data();
      for (int j = from; j < to; ++j) {
        double d2 = 0;
        for (int d = 0; d < D; ++d) {
          const double u = xi[d] - X[j * D + d];
          d2 = d == 0 ? u * u : d2 + u * u;
        }
        const bool listed = d2 < cut_i[species[j]];
        out[q] = j;
        PI[p] = i;
        PJ[p] = j;
        PT[p] = static_cast<std::uint8_t>(type_i + species[j]);
        q += listed;
        p += listed;
      }
    };
    const int c0 = cell % dims[0];
    const int c1 = (cell / dims[0]) % dims[1];
    const int c2 = D == 3 ? int(cell / plane) : 0;
    const int lo0 = c0 > 0 ? -1 : 0, hi0 = c0 < dims[0] - 1 ? 1 : 0;
    // own cell after i, and the next cell in the same grid row
    scan(i + 1, cell_start_[cell + 1 + hi0]);
    // the grid row above (and in 3D the whole plane above): three cells, contiguous in index
    auto scan_row = [&](long row_first) {  // row_first: the cell at c0 in that grid row
      scan(cell_start_[row_first + lo0], cell_start_[row_first + hi0 + 1]);
    };
    if (c1 < dims[1] - 1) scan_row(cell + dims[0]);
    if constexpr (D == 3) {
      if (c2 < dims[2] - 1)
        for (int d1 = -1; d1 <= 1; ++d1) {
          const int r1 = c1 + d1;
          if (r1 < 0 || r1 >= dims[1]) continue;
          scan_row(cell + plane + long(d1) * dims[0]);
        }
    }
    // close the row: its slack (scan() left room for it) and its wall mask
    row_end_[i] = q;
    std::fill(nbr_.begin() + q, nbr_.begin() + q + kRowSlack, -1);
    q += kRowSlack;
    wall_mask_[i] = walls_in_reach(s.x[i], 0.5 * wall_diameter(s, species[i]) + skin_, hopper);
  }
  nbr_.resize(q);
  row_start_[n] = q;
  slots_indexed_ = false;
  for (; next_block <= nb; ++next_block) pair_start_[next_block] = p;
  run_fresh_ = true;
}

template <int D>
void NeighborList<D>::restore(Snapshot snap, int n) {
  force_ = true;
  const auto bad = [](const std::string& what) { throw std::invalid_argument("neighbour list: " + what); };
  builds_ = snap.builds;
  grid_ = false;  // the grid is not in a checkpoint: for_each_near() declines until the next build
  relocated_.clear();
  if (snap.force) return;  // a rebuild was due anyway
  if (int(snap.x_ref.size()) != n || int(snap.row_start.size()) != n + 1 || int(snap.row_end.size()) != n ||
      int(snap.wall_mask.size()) != n)
    bad("arrays of the wrong size");
  const int total = static_cast<int>(snap.nbr.size());
  for (int i = 0; i < n; ++i) {
    if (snap.row_start[i] < 0 || snap.row_start[i] > snap.row_end[i] || snap.row_end[i] > snap.row_start[i + 1] ||
        snap.row_start[i + 1] > total)
      bad("row bounds out of order");
    for (int k = snap.row_start[i]; k < snap.row_end[i]; ++k)
      if (snap.nbr[k] <= i || snap.nbr[k] >= n) bad("an entry outside 0 .. N-1 or not above its row");
  }
  if (snap.row_start[n] != total) bad("row bounds out of order");
  x_ref_ = std::move(snap.x_ref);
  row_start_ = std::move(snap.row_start);
  row_end_ = std::move(snap.row_end);
  nbr_ = std::move(snap.nbr);
  // unused slots hold -1 (a checkpoint of engine 0.3.0 could hold stale entries there)
  for (int i = 0; i < n; ++i) std::fill(nbr_.begin() + row_end_[i], nbr_.begin() + row_start_[i + 1], -1);
  slots_indexed_ = false;
  run_fresh_ = false;
  wall_mask_ = std::move(snap.wall_mask);
  builds_ = snap.builds;
  force_ = false;
  block_lists_stale_ = true;
}

template <int D>
void NeighborList<D>::relocate(int i, const ParticleState<D>& s, const Hopper<D>& hopper) {
  if (force_) return;  // a rebuild is due anyway
  block_lists_stale_ = true;
  run_fresh_ = false;
  // before anything can fail: for_each_near() must see it (and declines once the list of
  // relocations is as long as a scan of every item)
  const int n = s.size();
  if (static_cast<int>(relocated_.size()) < n)
    relocated_.push_back(i);
  else
    grid_ = false;
  // out: its own row, and its entries in the rows of lower-numbered particles
  std::fill(nbr_.begin() + row_start_[i], nbr_.begin() + row_end_[i], -1);
  row_end_[i] = row_start_[i];
  for (int k = 0; k < i; ++k) {
    int* begin = nbr_.data() + row_start_[k];
    int* end = nbr_.data() + row_end_[k];
    int* at = std::lower_bound(begin, end, i);
    if (at != end && *at == i) {
      std::copy(at + 1, end, at);
      *(end - 1) = -1;  // unused slots hold -1 (update_block_lists)
      --row_end_[k];
    }
  }
  // in: the same criterion as build(), against the reference positions of the others, so the
  // list stays valid while every particle stays within skin/2 of its reference
  x_ref_[i] = s.x[i];
  const int si = s.species[i];
  for (int j = 0; j < n; ++j) {
    if (j == i || excluded(i, j)) continue;
    const double c = 0.5 * (s.sp.sigma[si] + s.sp.sigma[s.species[j]]) + std::max(extra(i), extra(j)) + skin_;
    if ((x_ref_[i] - x_ref_[j]).squaredNorm() >= c * c) continue;
    const int row = std::min(i, j), other = std::max(i, j);
    if (row_end_[row] == row_start_[row + 1]) {  // no room left: rebuild at the next update
      force_ = true;
      return;
    }
    int* begin = nbr_.data() + row_start_[row];
    int* end = nbr_.data() + row_end_[row];
    int* at = std::lower_bound(begin, end, other);
    std::copy_backward(at, end, end + 1);
    *at = other;
    ++row_end_[row];
  }
  wall_mask_[i] = walls_in_reach(x_ref_[i], 0.5 * wall_diameter(s, si) + skin_, hopper);
}

template class NeighborList<2>;
template class NeighborList<3>;

}  // namespace beverloo
