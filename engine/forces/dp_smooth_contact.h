#pragma once
/// \file dp_smooth_contact.h
/// \brief Contacts of the smooth ("frictionless") DP model (physics.md 4, paper Appendix A):
/// edge i of polygon m is a circulo-line of width delta_m; against vertex j of polygon n
/// (m != n; and m = n, see self-contact below) the energy is (E_c/2)(1 - d/delta_mn)^2 for d < delta_mn with
///  - d the perpendicular distance |(r_j - r_i) . nhat_i| when the foot of r_j lies on the edge
///    (0 <= t <= 1): a capsule is symmetric, so a vertex behind an edge (in a concave pocket of
///    a polygon wrapped around a corner) is as close as one in front; the reaction -F on the edge
///    is split between its end vertices by the lever rule, (1 - t) and t, the exact gradient;
///  - d = |r_j - r_i| (the edge's start vertex) when the foot lies before the edge (t < 0).
///
/// Decision (corner rule): the start-vertex branch applies only where r_j is also beyond the
/// previous edge (its foot there has t_prev > 1), i.e. in the wedge outside both edge slabs.
/// The literal rule would count a vertex near a convex corner twice (once by the edge, once by
/// the next edge's start vertex) and its energy would jump when the vertex leaves the slab;
/// with the wedge rule the energy is continuous and its gradient too at convex corners.
/// Where the two slabs overlap (a concave corner seen from the vertex, or the vertex inside the
/// polygon), both edges count the vertex; within delta_mn of the corner the corner's energy
/// (E_c/2)(1 - |r_j - r_i|/delta_mn)^2 is taken away once (corner_in_both_slabs). That is each
/// slab's energy on its boundary through the corner, so the sum stays continuous where the
/// vertex leaves either slab (engine 0.5.0; before, the energy jumped there: ~1e-3 of the kinetic
/// energy per event in a conservative pile, docs/validation.md).
///
/// Kinetic friction acts between the vertex and the contact point P on the edge:
/// F_j = -mu (v_j - v_P), v_P = (1 - t) v_i + t v_next(i), split on the edge by the lever rule
/// (dissipative: power -mu |v_j - v_P|^2 per contact; momentum conserving). With a split law
/// (mu_n != mu_t) the normal is the edge's (or, at a corner, the vertex-vertex line).
///
/// Self-contact (a decision, not in the paper): the edges of a polygon also repel its own
/// vertices but the edge's ends, without friction. At rest these lie beyond the ends of each
/// other's edges, so only a folding polygon feels it; it keeps soft polygons (K_l ~ 1,
/// K_b ~ 1e-2) simple. The vertex one place beyond either end of an edge (a fold pair) is
/// handled apart: its capsule is capped at the shared vertex and not at the other end.
///
/// Every edge-vertex pair in contact is found from the vertex Verlet
/// list through the edge's nearer end vertex: a vertex within delta_mn of an edge is within
/// |edge|/2 + delta_mn of that end (the foot of its perpendicular, or the corner, is at most
/// half the edge away from it), and each vertex's list reach covers half its edges' bounds
/// (DpForceField). A list pair (a, b) evaluates, for each of the two edges meeting at a, that
/// edge against vertex b if a is the edge's end nearer to b (ties: the start vertex), and the
/// same with a and b swapped; so every edge-vertex pair is counted exactly once, and a
/// stretched edge widens the search only around its own vertices.
#include <array>
#include <vector>
#include <optional>
#include <utility>

#include "../dp/polygons.h"
#include "../neighbor/neighbor_list.h"
#include "force_term.h"
#include "harmonic_overlap.h"
#include "kinetic_friction.h"

namespace beverloo {

class DpSmoothContact final : public ForceTerm<2> {
 public:
  /// The smooth model's contact: edges of width shape.delta, with corners and friction.
  /// E_c_vertex: the energy scale of the corner (vertex-vertex) branch, E_c unless given
  /// (dp.E_c_vertex; the authors' code: E_c/2)
  DpSmoothContact(NeighborList<2>& list, const PolygonSet& p, const DpShape& shape, double E_c,
                  FrictionLaw friction, std::optional<double> E_c_vertex = std::nullopt)
      : DpSmoothContact(list, p, {shape.delta[0], shape.delta[1]}, E_c, friction, true, "dp_smooth_contact") {
    eps_vertex_ = E_c_vertex.value_or(E_c);
  }
  /// The rough model's edge core: each edge a circulo-line of width l0/2 (half the vertex
  /// disks'), slabs only (the disks hold the corners), no friction, and energy scale E_c/4 so
  /// that its stiffness per unit overlap, E/width^2, is the disks' (the time step stays the
  /// same). A foreign disk resting in the cusp between two disks of an unstretched edge is
  /// 0.87 l0 from the edge, so the core does not act there; it acts where a soft edge has
  /// stretched (K_l ~ 1: seen to 3.8 l0) far enough for a vertex, of another polygon or of
  /// the edge's own, to slip between two disks, and keeps such polygons simple. Not in the
  /// paper: docs/validation.md.
  static DpSmoothContact rough_edge_core(NeighborList<2>& list, const PolygonSet& p, const DpShape& shape,
                                         double E_c) {
    return DpSmoothContact(list, p, core_widths(shape), kRoughCoreEnergyFraction * E_c, FrictionLaw{}, false,
                           "dp_rough_edge_core");
  }
  static std::array<double, 2> core_widths(const DpShape& shape) { return {0.5 * shape.l0[0], 0.5 * shape.l0[1]}; }
  static constexpr double kRoughCoreEnergyFraction = 0.25;

  /// The rough model's fold barrier: each edge against the vertex one place beyond either of
  /// its ends, of its own polygon (the pairs the core leaves out), slabs only, width
  /// kRoughFoldWidth l0 and energy scale E_c kRoughFoldWidth^2 (the disks' stiffness per unit
  /// overlap again). At rest such a vertex is beyond the edge's end; it reaches the slab only
  /// where the polygon folds at the shared vertex (interior angle below 90 degrees). The edge is
  /// capped at the shared vertex (the fold loop in the .cpp), so an edge compressed below the
  /// width is also pushed apart. Without this term a soft polygon (K_l ~ 1, K_b ~ 1e-2) folds
  /// through itself at a vertex, where its disks two apart no longer meet. Not in the paper.
  static DpSmoothContact rough_fold_barrier(NeighborList<2>& list, const PolygonSet& p, const DpShape& shape,
                                            double E_c) {
    DpSmoothContact c(list, p, {kRoughFoldWidth * shape.l0[0], kRoughFoldWidth * shape.l0[1]},
                      kRoughFoldWidth * kRoughFoldWidth * E_c, FrictionLaw{}, false, "dp_rough_fold_barrier");
    c.pairs_ = false;
    c.folds_ = true;
    return c;
  }
  static constexpr double kRoughFoldWidth = 0.25;

  std::string_view name() const override { return name_; }
  TermOutput accumulate(const ParticleState<2>& s, VecArray<2>& f) override;
  /// The same sum, with the fold pairs tested only at the listed vertices (increasing): those
  /// where fold_may_act() holds, which DpForceField finds while it measures the edges for the
  /// shape terms (at most vertices are none). The same bits as accumulate() for the same state.
  TermOutput accumulate_with_folds(const ParticleState<2>& s, VecArray<2>& f, const std::vector<int>& fold_vertices);
  /// Whether the fold pairs at a vertex can act, from its two edges e_in (prev -> k) and e_out
  /// (k -> next), given as e_in . e_out and their squared lengths, and its species: where they
  /// meet at more than 90 degrees and both are at least the width long, neither fold vertex is
  /// in the other edge's slab nor within a cap. This is the fold loop's fast exit on u = -e_in,
  /// v = e_out: u . v < 0 exactly when e_in . e_out > 0 (negation is exact), |u|^2 = |e_in|^2.
  bool fold_may_act(double in_dot_out, double sq_in, double sq_out, int species) const {
    return folds_ && !(in_dot_out > 0 && sq_in >= width2_[species] && sq_out >= width2_[species]);
  }
  /// fold_may_act()'s two constants, for a loop that tests a whole polygon at once.
  bool has_folds() const { return folds_; }
  double fold_width2(int species) const { return width2_[species]; }
  /// OpenMP threads for the pairs: rows in fixed chunks (kRowsPerChunk vertices), each chunk's
  /// force writes logged and replayed in chunk order, so every count gives the same bits.
  void set_threads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  static constexpr int kRowsPerChunk = 1024;
  /// Friction force on each vertex alone (for the |F^mu| observable); overwrites out.
  void friction_forces(const ParticleState<2>& s, VecArray<2>& out) const;
  void set_friction_enabled(bool on) { friction_on_ = on; }
  /// Largest relative overlap 1 - d/delta_mn seen in the last accumulate().
  double max_overlap() const { return max_overlap_; }
  /// The vertex and the edge (its start vertex) of that largest overlap.
  std::pair<int, int> worst_contact() const { return worst_; }

 private:
  enum class Mode { Repulsion, RepulsionAndFriction, FrictionOnly };
  /// The repulsion of an edge and a vertex at distance d < delta_mn, a normal law of the seam
  /// (contact_laws.h): the harmonic law of the paper. The DP models have no job parameter
  /// that chooses another yet; one would make this a registry row as SpContact does.
  using NormalLaw = HarmonicOverlap;
  /// one_thread: whatever set_threads() said (friction_forces(), an observable, runs alone)
  template <Mode kMode>
  TermOutput loop(const ParticleState<2>& s, VecArray<2>& f, const std::vector<int>* fold_vertices = nullptr,
                  bool one_thread = false) const;
  struct View;  ///< the state's and the polygons' arrays as pointers (the .cpp)
  struct DirectSink;  ///< force writes into the array
  struct LogSink;     ///< force writes into a chunk's log
  /// One chunk's running sums (and the whole evaluation's).
  struct Acc {
    double energy = 0, power = 0, max_ov = 0;
    std::pair<int, int> worst{-1, -1};
  };
  struct ForceWrite {
    int vertex;
    Vec<2> force;
  };
  /// The two edges meeting at vertex a against vertex b, each if a is its end nearer to b.
  /// da: |r_b - r_a|^2
  template <Mode kMode, class Sink>
  void edges_at_vertex(const View& s, int a, int b, double da, Acc& acc, Sink& sink) const;
  /// Vertex b in both slabs of the edges at a, within delta of a: one corner energy taken away.
  template <class Sink>
  void corner_in_both_slabs(const View& s, int a, int b, double da, double dmn, Acc& acc, Sink& sink) const;
  /// Fold pairs (same polygon, b one place beyond an end of edge a) cap the edge at that end.
  enum class FoldCap { None, AtStart, AtEnd };
  template <Mode kMode, class Sink>
  void edge_vertex(const View& s, int a, int b, Acc& acc, Sink& sink, FoldCap cap = FoldCap::None) const;

  DpSmoothContact(NeighborList<2>& list, const PolygonSet& p, std::array<double, 2> width, double E_c,
                  FrictionLaw friction, bool corners, const char* name)
      : list_(list), p_(p), width_(width), width2_{width[0] * width[0], width[1] * width[1]}, eps_(E_c), eps_vertex_(E_c),
        law_(friction), corners_(corners), folds_(corners), name_(name) {}

  /// Not const: the evaluation brings the list's flat pair run up to date (update_block_lists).
  NeighborList<2>& list_;
  const PolygonSet& p_;
  std::array<double, 2> width_;  ///< edge (and vertex) contact width per species
  std::array<double, 2> width2_; ///< its square, w * w as the fold loop computes it
  double eps_;
  double eps_vertex_;  ///< the corner (vertex-vertex) branch's energy scale
  FrictionLaw law_;
  bool corners_;        ///< false: slabs only (the rough core and fold barrier)
  bool pairs_ = true;   ///< edge-vertex pairs from the list (all but the fold barrier)
  bool folds_;          ///< each edge against the vertex one beyond either end, same polygon
  const char* name_;
  bool friction_on_ = true;
  int threads_ = 1;
  // written by the evaluation loop, which friction_forces() (const) shares
  mutable double max_overlap_ = 0;
  mutable std::pair<int, int> worst_{-1, -1};
  mutable std::vector<Acc> chunk_acc_;                  ///< per chunk of rows
  mutable std::vector<double> edge_sq_;      ///< per vertex k: |r_next(k) - r_k|^2 this evaluation
  mutable std::vector<double> edge_sq_max_;  ///< per vertex: the larger of its two edges' edge_sq_
  mutable std::vector<std::vector<ForceWrite>> logs_;  ///< per chunk of rows (threads > 1)
  mutable std::vector<int> chunk_pairs_;  ///< per chunk of rows, its first pair in the list's pair run (and the end)
  /// Pairs tested per batch before the passing ones are evaluated (see loop()).
  static constexpr int kTestBatch = 64;
};

}  // namespace beverloo
