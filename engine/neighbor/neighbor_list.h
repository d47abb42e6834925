#pragma once
/// \file neighbor_list.h
/// \brief Verlet half list with a skin, built through a cell grid: O(N) per build, rebuilt only
/// when some particle has moved more than half the skin since the last build.
///
/// Each row i holds the j > i within sigma_ij + skin, sorted by j. Sorting makes the order in
/// which pair forces are summed depend only on which pairs overlap, not on when the list was
/// built, so a run resumed from a checkpoint (which rebuilds the list) stays bit-identical.
/// The same build records, per particle, which walls are within sigma_i/2 + skin.
#include <array>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "../geometry/hopper.h"
#include "../state.h"

namespace beverloo {

template <int D>
class NeighborList {
 public:
  explicit NeighborList(double skin) : skin_(skin) {}

  /// Rebuild if needed (or if forced); returns true if it rebuilt.
  bool update(const ParticleState<D>& s, const Hopper<D>& hopper) {
    if (!force_ && !moved_beyond_half_skin(s)) return false;
    build(s, hopper);
    return true;
  }
  void build(const ParticleState<D>& s, const Hopper<D>& hopper);
  /// Sorts the items by cell first (s is reordered: s.permute, through scratch), then builds:
  /// memory order follows space, so that the force loops find their neighbours in cache, and
  /// each row comes out in increasing index from half the neighbour cells. The SP model's build.
  void build_sorting(ParticleState<D>& s, const Hopper<D>& hopper, ParticleState<D>& scratch);
  /// Whether the list must be rebuilt, given the largest squared displacement of any item since
  /// the last build (see reference_positions()).
  bool due(double max_moved2) const { return force_ || max_moved2 > rebuild_distance2(); }
  /// The squared displacement beyond which the list is due: (skin / 2)^2.
  double rebuild_distance2() const { return 0.25 * skin_ * skin_; }
  /// due(), given whether some item moved beyond rebuild_distance2().
  bool due_after(bool moved_beyond) const { return force_ || moved_beyond; }
  /// Whether a rebuild has been forced (invalidate(), a relocation without room).
  bool forced() const { return force_; }
  /// Positions at the last build (a relocated item: at its relocation); empty before any build.
  const VecArray<D>& reference_positions() const { return x_ref_; }

  /// Blocks for threads: the items split into blocks() runs of consecutive indices, a number
  /// that depends on the item count alone (never on the threads), so that every thread count
  /// sums every force in the same order. Each block owns its items' forces: a pair inside a
  /// block is added to both items by the block; a pair across blocks (i in a lower block) is
  /// added to i by i's block and to j by j's block, from j's incoming list (the i of lower
  /// blocks whose row holds j, increasing). Items sorted by cell make blocks compact in space,
  /// so few pairs cross.
  /// Blocks are runs of items sorted by cell: slabs across the slowest grid axis, the whole
  /// being about n^(1/D) items thick. The pairs across a boundary are computed from both sides,
  /// so a slab should be many layers thick: kLayersPerBlock keeps them to a few per cent of all
  /// pairs (measured: 2 blocks cost case a of `bench` about 3 %, 5 blocks 13 %). Two blocks at
  /// least from kMinItemsForBlocks items on, so that two threads have work.
  static int block_count(int n) {
    if (n < kMinItemsForBlocks) return 1;
    const double layers = std::pow(static_cast<double>(n), 1.0 / D);
    return std::clamp(static_cast<int>(layers / kLayersPerBlock), 2, kMaxBlocks);
  }
  int blocks() const { return blocks_on_ ? block_count(static_cast<int>(row_end_.size())) : 1; }
  /// Blocks are for the SP force field (ForceField turns them on); a DP list keeps one block,
  /// so that its models' sums stay in the order they always had.
  void use_blocks(bool on) {
    blocks_on_ = on;
    block_lists_stale_ = true;
    run_fresh_ = false;  // its block boundaries change
  }
  int block_begin(int b) const {
    const long n = static_cast<long>(row_end_.size());
    return static_cast<int>(n * b / blocks());
  }
  /// The blocks' pair runs, incoming lists and late kicks (brought up to date if rows changed
  /// since they were made); species: the items' species, for pair_type().
  void update_block_lists(const std::uint8_t* species);
  /// Block b's pairs as one run: (pair_i()[k], pair_j()[k]) for k in pairs_begin(b) ..
  /// pairs_begin(b + 1), the rows of the block in order, each row's entries in order. The force
  /// loops walk this run rather than row by row: rows are short (2-3 entries in a 2D pile)
  /// and of varying length, and a loop per row paid a mispredicted branch at nearly every row's end.
  int pairs_begin(int b) const { return pair_start_[b]; }
  /// The items of block b with a wall in reach (a non-zero wall_mask), increasing: the walls'
  /// loop runs over these, a few per cent of all.
  const int* wall_items_begin(int b) const { return wall_items_.data() + wall_start_[b]; }
  const int* wall_items_end(int b) const { return wall_items_.data() + wall_start_[b + 1]; }
  const int* pair_i() const { return pair_i_.data(); }
  const int* pair_j() const { return pair_j_.data(); }
  /// Per pair of the runs, 2 species(i) + species(j): the index of the species-pair tables,
  /// without two loads from the species array per pair.
  const std::uint8_t* pair_type() const { return pair_type_.data(); }
  const int* incoming_begin(int j) const { return in_items_.data() + in_start_[j]; }
  const int* incoming_end(int j) const { return in_items_.data() + in_start_[j + 1]; }
  /// The items of block b with a non-empty incoming list, increasing (a block's boundary: a
  /// loop over these, not over all its items).
  const int* receivers_begin(int b) const { return receivers_.data() + receivers_start_[b]; }
  const int* receivers_end(int b) const { return receivers_.data() + receivers_start_[b + 1]; }
  /// Items whose velocity another block reads during the force pass (receivers, and the items
  /// of a row that reaches into a later block), increasing; late_kick(i) tells them apart. A
  /// pass that kicks each item as soon as its force is complete (ForceField::forces_and_kick)
  /// must leave these until every block is done.
  const std::vector<int>& late_kick_items() const { return late_items_; }
  const std::uint8_t* late_kick() const { return late_.data(); }

  /// Everything the list holds, for a checkpoint: a resumed run continues with the very list
  /// (and so the rebuild schedule and item order) of the uninterrupted one.
  struct Snapshot {
    VecArray<D> x_ref;
    std::vector<int> row_start, row_end, nbr;
    std::vector<std::uint8_t> wall_mask;
    bool force = true;
    std::int64_t builds = 0;
  };
  Snapshot snapshot() const { return {x_ref_, row_start_, row_end_, nbr_, wall_mask_, force_, builds_}; }
  /// Restores a snapshot of a list over n items; throws std::invalid_argument naming what does
  /// not fit (a damaged checkpoint) and leaves the list forced to rebuild.
  void restore(Snapshot snap, int n);
  /// Items with equal group ids are not listed as pairs (vertices of one polygon); the vectors
  /// must outlive the list. nullptr: all pairs (SP particles). With `first` (group g holds items
  /// first[g] .. first[g+1]-1, a ring) and ring >= 0, only pairs of one group at most `ring`
  /// places apart along the ring are left out: the others are self-contacts of a polygon.
  void set_groups(const std::vector<int>* group, const std::vector<int>* first = nullptr, int ring = -1) {
    group_ = group;
    first_ = first;
    exclude_ring_ = first ? ring : -1;
    force_ = true;
  }
  /// Per-item extra reach (nullptr: none): pairs are listed within sigma_ij +
  /// max(extra_i, extra_j) + skin. The smooth DP contact finds an edge from the nearer of its
  /// end vertices, so each vertex reaches beyond its contact diameter as far as half its
  /// longest edge requires (DpForceField::edge_reach); a pair (i, j) is evaluated for the
  /// edges at i and those at j, so it needs the larger of the two reaches, not their sum (with
  /// the sum the authors' smooth set searched about 2.4 times the area around a vertex). The
  /// vector must outlive the list; whoever changes it must invalidate() the list.
  /// Items of species k feel the walls within diameters[k] / 2 (instead of sigma[k] / 2): the
  /// wall masks reach that far (plus the skin). DP vertices whose wall contact is wider than
  /// their pair contact (dp.wall_width).
  void set_wall_diameters(std::array<double, 2> diameters) {
    wall_diameters_ = diameters;
    own_wall_diameters_ = true;
    force_ = true;
  }
  /// Walls whose force reaches farther behind them than any reach (DP thick walls: a side
  /// wall pushes a vertex back in from any distance beyond it,
  /// FunnelCores::walls_acting_beyond): `beyond(x, reach)` gives the bits of the walls whose
  /// force may act on an item within `reach` of x, and the wall masks take them too. Without
  /// it a deep item's wall force would depend on where it was at the last build (so on when
  /// the list was built, and a resumed run, whose list is built afresh, would leave the
  /// uninterrupted one).
  void set_walls_acting_beyond(std::function<std::uint8_t(const Vec<D>&, double)> beyond) {
    walls_beyond_ = std::move(beyond);
    force_ = true;
  }
  void set_extra_reach(const std::vector<double>* extra) {
    extra_ = extra;
    force_ = true;
  }
  /// Forces the next update() to rebuild.
  void invalidate() { force_ = true; }
  /// Particle i was moved far (reinjection): take it out of the list and put it back at its
  /// new position, so that one jump does not force a rebuild of everything. Rows stay sorted,
  /// so force sums are unchanged; a row without room falls back to invalidate().
  void relocate(int i, const ParticleState<D>& s, const Hopper<D>& hopper);

  /// Calls fn(k) for every item k that can lie within `reach` of point p, and returns true; or
  /// returns false, having called nothing, if the list cannot tell (then test every item).
  /// The candidates are the items binned at the last build in the cells around p, and the
  /// items relocated since: while the list is valid (no item farther than skin/2 from its
  /// reference position, as after update()), an item within reach of p was binned within
  /// reach + skin/2 of p, so in a neighbouring cell if that is at most the cell width. An item
  /// may come twice; fn must not move items. O(1) per call instead of O(N) (the reinjection's
  /// free-spot test).
  template <class Fn>
  bool for_each_near(const Vec<D>& p, double reach, Fn&& fn) const {
    if (force_ || !grid_ || reach + 0.5 * skin_ > cell_width_) return false;
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int d = 0; d < D; ++d) {
      const double at = std::floor((p[d] - grid_lo_[d]) / cell_width_);
      const int c = !(at > 0) ? 0 : (at > dims_[d] - 1 ? dims_[d] - 1 : static_cast<int>(at));  // NaN: 0
      lo[d] = std::max(c - 1, 0);
      hi[d] = std::min(c + 1, dims_[d] - 1);
    }
    for (int c2 = lo[2]; c2 <= hi[2]; ++c2)
      for (int c1 = lo[1]; c1 <= hi[1]; ++c1) {
        // a grid row's cells lo0 .. hi0 hold consecutive slots of the counting sort
        const long first = (long(c2) * dims_[1] + c1) * dims_[0];
        for (int k = cell_start_[first + lo[0]], end = cell_start_[first + hi[0] + 1]; k < end; ++k)
          fn(grid_sorted_ ? k : cell_items_[k]);
      }
    for (int k : relocated_) fn(k);
    return true;
  }

  const int* row_begin(int i) const { return nbr_.data() + row_start_[i]; }
  const int* row_end(int i) const { return nbr_.data() + row_end_[i]; }
  std::uint8_t wall_mask(int i) const { return wall_mask_[i]; }
  std::int64_t builds() const { return builds_; }
  std::size_t pairs() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < row_end_.size(); ++i) n += row_end_[i] - row_start_[i];
    return n;
  }
  double skin() const { return skin_; }

 private:
  bool moved_beyond_half_skin(const ParticleState<D>& s) const;
  /// The cell grid over s's bounding box: dims_, cell_of_, cell_start_ (prefix sums).
  void bin(const ParticleState<D>& s);
  /// Per species pair, the squared list cutoff (sigma_ab + skin)^2.
  struct Cutoffs {
    double c[2][2];
  };
  Cutoffs cutoffs(const Species& sp) const {
    Cutoffs out;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const double c = 0.5 * (sp.sigma[a] + sp.sigma[b]) + skin_;
        out.c[a][b] = c * c;
      }
    return out;
  }
  void start_build(const ParticleState<D>& s);
  /// build()'s rows, with or without per-item extra reach and groups (decided once per build)
  template <bool kExtra, bool kGroups>
  void build_rows(const ParticleState<D>& s, const Hopper<D>& hopper);
  /// The pair runs (pair_i_, pair_j_, pair_type_, pair_start_) from the rows.
  void make_pair_runs(const std::uint8_t* species);
  /// slot_row_ (the row of every slot of nbr_), if not made since the last build or restore.
  void index_slots();
  /// The walls within reach of a particle at x (a bit per wall), and those acting beyond.
  std::uint8_t walls_in_reach(const Vec<D>& x, double reach, const Hopper<D>& hopper) const;

  bool excluded(int i, int j) const {
    if (!group_) return false;
    const int g = (*group_)[i];
    if (g != (*group_)[j]) return false;
    if (exclude_ring_ < 0) return true;
    const int n = (*first_)[g + 1] - (*first_)[g];
    const int d = i > j ? i - j : j - i;
    return std::min(d, n - d) <= exclude_ring_;
  }

  double skin_;
  const std::vector<int>* group_ = nullptr;
  const std::vector<int>* first_ = nullptr;
  int exclude_ring_ = -1;
  const std::vector<double>* extra_ = nullptr;
  std::array<double, 2> wall_diameters_{};
  bool own_wall_diameters_ = false;
  double wall_diameter(const ParticleState<D>& s, int species) const {
    return own_wall_diameters_ ? wall_diameters_[species] : s.sp.sigma[species];
  }
  double extra(int i) const { return extra_ ? (*extra_)[i] : 0.0; }
  bool force_ = true;
  std::int64_t builds_ = 0;
  VecArray<D> x_ref_;
  /// Row i holds nbr_[row_start_[i], row_end_[i]); up to row_start_[i + 1] is room for relocate().
  /// Unused slots (the room) hold -1; slot_row_[k]: the row that slot k belongs to (fixed
  /// between builds: relocate() changes row_end_ only).
  std::vector<int> row_start_, row_end_, nbr_, slot_row_;
  static constexpr int kRowSlack = 4;
  static constexpr double kLayersPerBlock = 16;
  static constexpr int kMinItemsForBlocks = 1000;
  static constexpr int kMaxBlocks = 64;
  std::vector<int> in_start_, in_items_, receivers_, receivers_start_, late_items_;
  std::vector<std::uint8_t> late_;
  std::vector<int> pair_i_, pair_j_, pair_start_, wall_items_, wall_start_;
  std::vector<std::uint8_t> pair_type_;
  bool block_lists_stale_ = true;
  /// The pair runs were written by build_sorting() itself (update_block_lists() then skips
  /// its pass over the slots); slot_row_ is made only for that pass, when it is needed.
  bool run_fresh_ = false, slots_indexed_ = false;
  bool blocks_on_ = false;
  std::vector<std::uint8_t> wall_mask_;
  std::function<std::uint8_t(const Vec<D>&, double)> walls_beyond_;
  // cell grid (counting sort), kept between builds so that builds allocate nothing
  std::vector<int> cell_of_, cell_start_, cell_items_, cursor_, order_;
  /// build(): each cell item's position, species, extra reach and group, in cell order
  VecArray<D> cell_x_;
  std::vector<std::uint8_t> cell_species_;
  std::vector<double> cell_extra_;
  std::vector<int> cell_group_;
  std::array<int, 3> dims_{1, 1, 1};
  // the grid of the last build, for for_each_near(): its origin and cell width, whether its
  // cells hold index ranges (build_sorting) or lists in cell_items_ (build), whether it exists
  // (not after a restore), and the items relocated since it was made
  Vec<D> grid_lo_ = Vec<D>::Zero();
  double cell_width_ = 0;
  bool grid_sorted_ = false, grid_ = false;
  std::vector<int> relocated_;
};

}  // namespace beverloo
