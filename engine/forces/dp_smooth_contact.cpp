#include "dp_smooth_contact.h"

#include <algorithm>
#include <cmath>

#include "harmonic_overlap.h"
#include "kinetic_friction.h"
#include "parallel_chunks.h"

namespace beverloo {

/// The arrays the evaluation reads, as local pointers: through the containers GCC reloaded each
/// array's base pointer after every force store (the stores might alias them). The operations
/// are the same, so the same bits.
struct DpSmoothContact::View {
  const Vec<2>* x;
  const Vec<2>* v;
  const std::uint8_t* species;
  const int* next;
  const int* prev;
  const int* owner;
  Vec<2>* f;
  const double* edge_sq;  ///< per vertex k: |r_next(k) - r_k|^2, as may_touch computed it in place
  double width[2];  ///< copies of width_, eps_, eps_vertex_ (members could be aliased by the stores too)
  double eps, eps_vertex;
};

/// Where the evaluation's force writes go: straight into the force array, or (threads) into a
/// chunk's log that is replayed in chunk order, so that every force sums the same numbers in the
/// same order whatever the thread count (x - y and x + (-y) are the same IEEE operation).
struct DpSmoothContact::DirectSink {
  Vec<2>* f;
  void add(int k, const Vec<2>& v) { f[k] += v; }
  void sub(int k, const Vec<2>& v) { f[k] -= v; }
};
struct DpSmoothContact::LogSink {
  std::vector<ForceWrite>* log;
  void add(int k, const Vec<2>& v) { log->push_back({k, v}); }
  void sub(int k, const Vec<2>& v) { log->push_back({k, -v}); }
};

template <DpSmoothContact::Mode kMode, class Sink>
void DpSmoothContact::edge_vertex(const View& s, int a, int b, Acc& acc, Sink& sink, FoldCap cap) const {
  const int an = s.next[a];
  const Vec<2> ra = s.x[a];
  const Vec<2> e = s.x[an] - ra;
  const Vec<2> q = s.x[b] - ra;
  const double e2 = e.squaredNorm();
  const double t = q.dot(e) / e2;
  const double dmn = 0.5 * (s.width[s.species[a]] + s.width[s.species[b]]);
  double d, w_start, w_end;  // distance; lever weights of the edge's start and end vertices
  double eps = s.eps;         // the energy scale: the corner branch's is eps_vertex_
  Vec<2> dir;                // unit vector along which d grows when vertex b moves
  // contact with one end vertex of the edge (a corner, or a fold pair's cap); r = r_b - that end
  auto to_end_vertex = [&](const Vec<2>& r, bool at_start) {
    const double d2 = r.squaredNorm();
    if (d2 >= dmn * dmn) return false;
    d = std::sqrt(d2);
    dir = r / d;
    w_start = at_start ? 1 : 0;
    w_end = at_start ? 0 : 1;
    return true;
  };
  if (t >= 0 && t <= 1) {
    const double inv_len = 1.0 / std::sqrt(e2);
    dir = Vec<2>(e[1] * inv_len, -e[0] * inv_len);  // outward normal (counter-clockwise polygon)
    d = q.dot(dir);
    if (d >= dmn || d <= -dmn) return;
    if (d < 0) {  // behind the edge: the capsule pushes the vertex further behind it
      d = -d;
      dir = -dir;
    }
    w_start = 1 - t;
    w_end = t;
  } else if (t < 0 && cap == FoldCap::AtStart) {
    // the fold pair's shared vertex: the distance to it is the length of the vertex's own edge
    // to it, which no other term claims (see the fold loop)
    if (!to_end_vertex(q, true)) return;
  } else if (t > 1 && cap == FoldCap::AtEnd) {
    if (!to_end_vertex(s.x[b] - s.x[an], false)) return;
  } else if (t < 0 && corners_ && cap == FoldCap::None) {
    // Inside the previous edge's slab (t_prev <= 1) the previous edge has the contact. t_prev
    // is computed with the very operations of that edge's own test, so that exactly one of the
    // two branches holds on the boundary.
    const Vec<2> rp = s.x[s.prev[a]];
    const Vec<2> ep = ra - rp;
    if ((s.x[b] - rp).dot(ep) / ep.squaredNorm() <= 1) return;
    if (!to_end_vertex(q, true)) return;
    eps = s.eps_vertex;
  } else {
    return;  // beyond the end: the next edge's start vertex (its wedge) or its slab; or no corners
  }
  if constexpr (kMode != Mode::FrictionOnly) {
    double law_ov;  // the law's overlap 1 - d * (1/dmn); max_ov keeps its own d / dmn (its bits)
    const double repulsion = NormalLaw::force(eps, 1.0 / dmn, d, acc.energy, law_ov);  // -dU/dd
    const double ov = 1.0 - d / dmn;
    if (ov > acc.max_ov) {
      acc.max_ov = ov;
      acc.worst = {b, a};
    }
    const Vec<2> fb = repulsion * dir;  // on the vertex, away from the edge
    sink.add(b, fb);
    sink.sub(a, w_start * fb);
    sink.sub(an, w_end * fb);
  }
  if constexpr (kMode != Mode::Repulsion) {
    if (s.owner[a] == s.owner[b]) return;  // kinetic friction acts between particles only
    const Vec<2> v_contact = w_start * s.v[a] + w_end * s.v[an];
    const Vec<2> rel = s.v[b] - v_contact;
    // split along the contact normal (the edge's normal, or the corner's vertex-vertex line)
    const Vec<2> ff = law_.split() ? kinetic_friction_force<2>(law_, s.v[b], v_contact, dir) : Vec<2>(-law_.mu_t * rel);
    acc.power += ff.dot(rel);
    sink.add(b, ff);
    sink.sub(a, w_start * ff);
    sink.sub(an, w_end * ff);
  }
}

template <DpSmoothContact::Mode kMode, class Sink>
void DpSmoothContact::edges_at_vertex(const View& s, int a, int b, double da, Acc& acc, Sink& sink) const {
  // The same expression for the same pair of points wherever it is evaluated, so that the
  // nearer-end test of an edge gives one answer from either end (exactly one end counts it).
  // da = dist2(a), from the row loop (|r_a - r_b|^2 and |r_b - r_a|^2 are the same bits). The
  // row loop's dmn is not passed in: recomputed here it measured faster (0.95 passed, 6 runs).
  auto dist2 = [&](int u) { return (s.x[b] - s.x[u]).squaredNorm(); };
  // A vertex one place beyond an edge's end (b = next(next(a)) or prev(prev(a)) of the same
  // polygon) is the fold loop's (the list leaves out its pair with that end).
  const int an = s.next[a], ap = s.prev[a];
  // Cheap rejection before the projection: from its nearer end a, the foot of b lies at most
  // half the edge away, so b is at least sqrt(da - |e|^2/4) from the edge (and sqrt(da) from a
  // corner); beyond the contact width no branch of edge_vertex acts. Most list pairs ended
  // already in the row loop, at this bound for the longest of the four edges (rough lists reach
  // a disk diameter, vertices in contact sit ~0.87 l0 from a core edge); here each edge's own.
  // The margin keeps rounding from ever skipping a pair that edge_vertex would count.
  const double dmn = 0.5 * (s.width[s.species[a]] + s.width[s.species[b]]);
  auto may_touch = [&](int edge_start) { return da <= (dmn * dmn + 0.25 * s.edge_sq[edge_start]) * (1 + 1e-9); };
  // What edge_vertex can count, told before its divisions and square root: b farther than
  // the width from the edge's line, |(r_b - r_start) x e| > dmn |e|, touches neither the slab
  // (the slab's d is that distance) nor the start corner (on the line: at least as far); b
  // beyond the edge's end (t > 1) is the next edge's; b before its start (t < 0) only its start
  // corner's, within dmn of it (start_d2 is the corner's own |r_b - r_start|^2, the same bits).
  // Each test has a margin far above its rounding (a few ulp), so no pair that edge_vertex
  // would count is skipped: the same bits. In a dense pile of soft polygons, flattened against
  // each other, b lies near the line of several edges along a contact: two of three calls that
  // pass the line test end at t outside the edge.
  const Vec<2> rb = s.x[b];
  auto may_count = [&](const Vec<2>& start, const Vec<2>& end, double e2, double start_d2) {
    const Vec<2> q = rb - start, e = end - start;
    const double cross = q[0] * e[1] - q[1] * e[0];
    if (cross * cross > dmn * dmn * e2 * (1 + 1e-9)) return false;
    const double qe = q[0] * e[0] + q[1] * e[1];  // t = qe / e2
    if (qe > e2 * (1 + 1e-9)) return false;
    return !(qe < -1e-200 * e2 && start_d2 >= dmn * dmn);
  };
  const Vec<2> ra = s.x[a];
  if (b != s.next[an] && may_touch(a) && da <= dist2(an) && may_count(ra, s.x[an], s.edge_sq[a], da))
    edge_vertex<kMode>(s, a, b, acc, sink);  // edge a -> next
  if (b != s.prev[ap] && may_touch(ap)) {
    const double d_ap = dist2(ap);
    if (da < d_ap && may_count(s.x[ap], ra, s.edge_sq[ap], d_ap))
      edge_vertex<kMode>(s, ap, b, acc, sink);  // edge prev -> a
  }
  if constexpr (kMode != Mode::FrictionOnly)
    if (corners_ && da < dmn * dmn && b != an && b != ap) corner_in_both_slabs(s, a, b, da, dmn, acc, sink);
}

template <class Sink>
void DpSmoothContact::corner_in_both_slabs(const View& s, int a, int b, double da, double dmn, Acc& acc, Sink& sink) const {
  // Vertex b in the slabs of both edges at a (a concave corner seen from b, or b inside the
  // polygon): each slab counts b, and each slab's energy at its boundary through a is the
  // corner's, (E_c/2)(1 - |r_b - r_a|/delta)^2. Subtracting that once here makes the sum
  // continuous where b leaves either slab (the wedge rule alone dropped it there: a jump) and
  // counts b once at the corner itself. t and t_prev with the very operations of edge_vertex.
  const Vec<2> ra = s.x[a], rb = s.x[b];
  const Vec<2> e = s.x[s.next[a]] - ra;
  const double t = (rb - ra).dot(e) / e.squaredNorm();
  if (t < 0 || t > 1) return;
  const Vec<2> rp = s.x[s.prev[a]];
  const Vec<2> ep = ra - rp;
  const double t_prev = (rb - rp).dot(ep) / ep.squaredNorm();
  if (t_prev < 0 || t_prev > 1) return;
  const double d = std::sqrt(da);
  if (d == 0) return;
  double corner_energy = 0, law_ov;
  const double repulsion = NormalLaw::force(s.eps, 1.0 / dmn, d, corner_energy, law_ov);
  acc.energy -= corner_energy;
  const Vec<2> fb = (repulsion / d) * (rb - ra);  // the corner's repulsion on b, taken away
  sink.sub(b, fb);
  sink.add(a, fb);
}

template <DpSmoothContact::Mode kMode>
TermOutput DpSmoothContact::loop(const ParticleState<2>& s, VecArray<2>& f, const std::vector<int>* fold_vertices,
                                 bool one_thread) const {
  const int n = s.size();
  // Each edge's squared length once per evaluation (the per-pair test below reads it for both
  // ends, and each list pair for four edges), and per vertex the larger of its two edges'.
  if (pairs_) {
    if (static_cast<int>(edge_sq_.size()) < n) {  // only when N grows
      edge_sq_.resize(n);
      edge_sq_max_.resize(n);
    }
    const Vec<2>* x = s.x.data();
    const int* next = p_.next.data();
    const int* prev = p_.prev.data();
    for (int k = 0; k < n; ++k) edge_sq_[k] = (x[next[k]] - x[k]).squaredNorm();
    for (int k = 0; k < n; ++k) edge_sq_max_[k] = std::max(edge_sq_[k], edge_sq_[prev[k]]);
  }
  const View view{s.x.data(), s.v.data(),  s.species.data(), p_.next.data(), p_.prev.data(), p_.owner.data(),
                  f.data(),   edge_sq_.data(), {width_[0], width_[1]}, eps_, eps_vertex_};
  // The list's rows in fixed chunks of vertices; each chunk's sums (energy, power, largest
  // overlap) are its own and are added in chunk order, whatever the thread count.
  const int chunks = pairs_ ? (n + kRowsPerChunk - 1) / kRowsPerChunk : 0;
  if (static_cast<int>(chunk_acc_.size()) < chunks) chunk_acc_.resize(chunks);  // only when N grows
  // The list's pairs as one flat run in row order (NeighborList::pairs_begin: rows are short,
  // 0-2 entries in a pile, and a loop per row paid a mispredicted branch at most rows' ends),
  // and per chunk of rows its first pair: the pairs of rows below a bound, pair_i increasing.
  const int* PI = nullptr;
  const int* PJ = nullptr;
  if (pairs_) {
    list_.update_block_lists(s.species.data());
    PI = list_.pair_i();
    PJ = list_.pair_j();
    const int run_end = list_.pairs_begin(list_.blocks());  // the DP list keeps one block
    if (static_cast<int>(chunk_pairs_.size()) < chunks + 1) chunk_pairs_.resize(chunks + 1);  // only when N grows
    for (int c = 0; c <= chunks; ++c)
      chunk_pairs_[c] = c == chunks ? run_end
                                    : static_cast<int>(std::lower_bound(PI, PI + run_end, c * kRowsPerChunk) - PI);
  }
  auto rows = [&](int c, auto& sink) {
    Acc acc;
    const Vec<2>* x = view.x;
    const std::uint8_t* species = view.species;
    const double* sq_max = edge_sq_max_.data();
    // Most listed pairs touch nowhere: every branch of edges_at_vertex, from either end, needs
    // d2 within may_touch's bound for one of the four edges at i and j (the corner within
    // dmn^2, less). The bound with the longest of them is at least each one's (each operation
    // rounds monotonically), so a pair beyond it is skipped for sure. The test runs over a
    // batch of pairs without a branch (about one pair in three passes, unpredictably), keeping
    // the passing ones in order; then those are evaluated in that order: the same sums.
    int batch[kTestBatch];
    double batch_d2[kTestBatch];
    for (int k = chunk_pairs_[c], end = chunk_pairs_[c + 1]; k < end;) {
      const int stop = std::min(end, k + kTestBatch);
      int passed = 0;
      for (; k < stop; ++k) {
        const int i = PI[k], j = PJ[k];
        const double d2 = (x[j] - x[i]).squaredNorm();
        const double dmn = 0.5 * (view.width[species[i]] + view.width[species[j]]);
        batch[passed] = k;
        batch_d2[passed] = d2;
        passed += !(d2 > (dmn * dmn + 0.25 * std::max(sq_max[i], sq_max[j])) * (1 + 1e-9));
      }
      for (int q = 0; q < passed; ++q) {
        const int i = PI[batch[q]], j = PJ[batch[q]];
        edges_at_vertex<kMode>(view, i, j, batch_d2[q], acc, sink);
        edges_at_vertex<kMode>(view, j, i, batch_d2[q], acc, sink);
      }
    }
    chunk_acc_[c] = acc;
  };
  if (threads_ == 1 || one_thread) {
    DirectSink sink{f.data()};
    for (int c = 0; c < chunks; ++c) rows(c, sink);
  } else {
    if (static_cast<int>(logs_.size()) < chunks) logs_.resize(chunks);  // only when N grows
    for_each_chunk(threads_, chunks, [&](int c) {
      logs_[c].clear();  // keeps its capacity: no allocation once the logs have grown
      LogSink sink{&logs_[c]};
      rows(c, sink);
    });
    Vec<2>* F = f.data();
    for (int c = 0; c < chunks; ++c)
      for (const ForceWrite& w : logs_[c]) F[w.vertex] += w.force;
  }
  Acc total;
  for (int c = 0; c < chunks; ++c) {
    const Acc& a = chunk_acc_[c];
    total.energy += a.energy;
    total.power += a.power;
    if (a.max_ov > total.max_ov) {  // the first largest, as one pass in row order finds it
      total.max_ov = a.max_ov;
      total.worst = a.worst;
    }
  }
  // Folds: each edge against the vertex one place beyond either of its ends, of its own polygon
  // (at rest beyond the edge's end, so nothing; they meet only where the polygon folds back on
  // itself at the shared vertex k, which soft bending allows). The capsule is capped at k: on
  // the slab's boundary at k the vertex is one edge from k, so without the cap the energy
  // would jump there whenever that edge is compressed below the width. With it, an edge
  // shorter than the width is pushed apart from both its ends' fold pairs (energy
  // eps (1 - l/width)^2), which keeps it from collapsing through zero, another way to fold.
  // Not for the rough core (l0/2 is within reach of a compressed edge, and the core has no
  // caps): the rough model has a narrower term of its own for this (rough_fold_barrier).
  // Few vertices: one thread, after the pairs.
  DirectSink sink{f.data()};
  auto fold_pairs_at = [&](int k) {
    edge_vertex<kMode>(view, view.prev[k], view.next[k], total, sink, FoldCap::AtEnd);  // edge prev(k) -> k
    edge_vertex<kMode>(view, k, view.prev[k], total, sink, FoldCap::AtStart);         // edge k -> next(k)
  };
  if (fold_vertices) {
    for (const int k : *fold_vertices) fold_pairs_at(k);
  } else {
    for (int k = 0; folds_ && k < n; ++k) {
      // Fast exit for the usual vertex: where the two edges at k meet at more than 90 degrees
      // (u . v < 0), each fold vertex projects beyond the shared end k of the other edge (t > 1
      // for edge prev -> k, t < 0 for k -> next; t - 1 and -t have the sign of -u . v), so only
      // the caps can act, and they act only on an edge shorter than the width. The cap tests
      // below compare the same squared lengths, so skipping changes no result (but for rounding
      // of t at exactly 90 degrees, where the slab's distance is the cap's). fold_may_act()
      // is this test on the edge vectors (u = -(r_k - r_prev) exactly).
      const Vec<2> u = view.x[view.prev[k]] - view.x[k];
      const Vec<2> v = view.x[view.next[k]] - view.x[k];
      const double w = view.width[view.species[k]];
      if (u.dot(v) < 0 && u.squaredNorm() >= w * w && v.squaredNorm() >= w * w) continue;
      fold_pairs_at(k);
    }
  }
  if constexpr (kMode != Mode::FrictionOnly) {
    max_overlap_ = total.max_ov;
    worst_ = total.worst;
  }
  return {total.energy, total.power};
}

TermOutput DpSmoothContact::accumulate(const ParticleState<2>& s, VecArray<2>& f) {
  return (friction_on_ && law_.active()) ? loop<Mode::RepulsionAndFriction>(s, f) : loop<Mode::Repulsion>(s, f);
}

TermOutput DpSmoothContact::accumulate_with_folds(const ParticleState<2>& s, VecArray<2>& f,
                                                  const std::vector<int>& fold_vertices) {
  return (friction_on_ && law_.active()) ? loop<Mode::RepulsionAndFriction>(s, f, &fold_vertices)
                                         : loop<Mode::Repulsion>(s, f, &fold_vertices);
}

void DpSmoothContact::friction_forces(const ParticleState<2>& s, VecArray<2>& out) const {
  out.assign(s.size(), Vec<2>::Zero());
  if (law_.active()) loop<Mode::FrictionOnly>(s, out, nullptr, /*one_thread=*/true);
}

}  // namespace beverloo
