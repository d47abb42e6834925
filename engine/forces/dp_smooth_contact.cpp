#include "dp_smooth_contact.h"

#include <cmath>

#include "harmonic_overlap.h"
#include "kinetic_friction.h"

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
  double width[2];  ///< copies of width_, eps_, eps_vertex_ (members could be aliased by the stores too)
  double eps, eps_vertex;
};

template <DpSmoothContact::Mode kMode>
void DpSmoothContact::edge_vertex(const View& s, int a, int b, double& energy, double& power, double& max_ov,
                                  FoldCap cap) const {
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
    const double repulsion = NormalLaw::force(eps, 1.0 / dmn, d, energy, law_ov);  // -dU/dd
    const double ov = 1.0 - d / dmn;
    if (ov > max_ov) {
      max_ov = ov;
      worst_ = {b, a};
    }
    const Vec<2> fb = repulsion * dir;  // on the vertex, away from the edge
    s.f[b] += fb;
    s.f[a] -= w_start * fb;
    s.f[an] -= w_end * fb;
  }
  if constexpr (kMode != Mode::Repulsion) {
    if (s.owner[a] == s.owner[b]) return;  // kinetic friction acts between particles only
    const Vec<2> v_contact = w_start * s.v[a] + w_end * s.v[an];
    const Vec<2> rel = s.v[b] - v_contact;
    // split along the contact normal (the edge's normal, or the corner's vertex-vertex line)
    const Vec<2> ff = law_.split() ? kinetic_friction_force<2>(law_, s.v[b], v_contact, dir) : Vec<2>(-law_.mu_t * rel);
    power += ff.dot(rel);
    s.f[b] += ff;
    s.f[a] -= w_start * ff;
    s.f[an] -= w_end * ff;
  }
}

template <DpSmoothContact::Mode kMode>
void DpSmoothContact::edges_at_vertex(const View& s, int a, int b, double& energy, double& power,
                                      double& max_ov) const {
  // The same expression for the same pair of points wherever it is evaluated, so that the
  // nearer-end test of an edge gives one answer from either end (exactly one end counts it).
  auto dist2 = [&](int u) { return (s.x[b] - s.x[u]).squaredNorm(); };
  const double da = dist2(a);
  // A vertex one place beyond an edge's end (b = next(next(a)) or prev(prev(a)) of the same
  // polygon) is the fold loop's (the list leaves out its pair with that end).
  const int an = s.next[a], ap = s.prev[a];
  // Cheap rejection before the projection: from its nearer end a, the foot of b lies at most
  // half the edge away, so b is at least sqrt(da - |e|^2/4) from the edge (and sqrt(da) from a
  // corner); beyond the contact width no branch of edge_vertex acts. Most list pairs end here
  // (rough lists reach a disk diameter, vertices in contact sit ~0.87 l0 from a core edge).
  // The margin keeps rounding from ever skipping a pair that edge_vertex would count.
  const double dmn = 0.5 * (s.width[s.species[a]] + s.width[s.species[b]]);
  auto may_touch = [&](int start, int end) {
    return da <= (dmn * dmn + 0.25 * (s.x[end] - s.x[start]).squaredNorm()) * (1 + 1e-9);
  };
  if (b != s.next[an] && da <= dist2(an) && may_touch(a, an))
    edge_vertex<kMode>(s, a, b, energy, power, max_ov);  // edge a -> next
  if (b != s.prev[ap] && da < dist2(ap) && may_touch(ap, a))
    edge_vertex<kMode>(s, ap, b, energy, power, max_ov);  // edge prev -> a
  if constexpr (kMode != Mode::FrictionOnly)
    if (corners_ && da < dmn * dmn && b != an && b != ap) corner_in_both_slabs<kMode>(s, a, b, da, dmn, energy);
}

template <DpSmoothContact::Mode kMode>
void DpSmoothContact::corner_in_both_slabs(const View& s, int a, int b, double da, double dmn, double& energy) const {
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
  energy -= corner_energy;
  const Vec<2> fb = (repulsion / d) * (rb - ra);  // the corner's repulsion on b, taken away
  s.f[b] -= fb;
  s.f[a] += fb;
}

template <DpSmoothContact::Mode kMode>
TermOutput DpSmoothContact::loop(const ParticleState<2>& s, VecArray<2>& f, const std::vector<int>* fold_vertices) const {
  double energy = 0, power = 0, max_ov = 0;
  const int n = s.size();
  const View view{s.x.data(), s.v.data(),  s.species.data(), p_.next.data(), p_.prev.data(), p_.owner.data(),
                  f.data(),   {width_[0], width_[1]}, eps_, eps_vertex_};
  for (int i = 0; pairs_ && i < n; ++i) {
    for (const int* p = list_.row_begin(i), *end = list_.row_end(i); p != end; ++p) {
      edges_at_vertex<kMode>(view, i, *p, energy, power, max_ov);
      edges_at_vertex<kMode>(view, *p, i, energy, power, max_ov);
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
  auto fold_pairs_at = [&](int k) {
    edge_vertex<kMode>(view, view.prev[k], view.next[k], energy, power, max_ov, FoldCap::AtEnd);  // edge prev(k) -> k
    edge_vertex<kMode>(view, k, view.prev[k], energy, power, max_ov, FoldCap::AtStart);         // edge k -> next(k)
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
  if constexpr (kMode != Mode::FrictionOnly) max_overlap_ = max_ov;
  return {energy, power};
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
  if (law_.active()) loop<Mode::FrictionOnly>(s, out);
}

}  // namespace beverloo
