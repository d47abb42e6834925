#include "dp_force_field.h"

#include <algorithm>
#include <sstream>

#include <emmintrin.h>

#include "../forces/sp_pairs_avx2.h"  // avx2::available()
#include "../integrate/sp_sweeps.h"

namespace beverloo {

std::array<double, 2> DpForceField::list_diameters(const DpShape& shape) {
  return {shape.delta[0], shape.delta[1]};
}

DpForceField::DpForceField(const SimConfig& c, const Hopper<2>& hopper, const PolygonSet& p, const DpShape& shape,
                           double E_c)
    : shape_(shape),
      poly_(p),
      list_(c.skin),
      area_(p, shape, {c.dp.K_a_of(0), c.dp.K_a_of(1)}),
      segments_(p, shape, {c.dp.K_l_of(0), c.dp.K_l_of(1)}),
      bending_(p, shape, c.dp.K_b),
      walls_(hopper, list_, c.E_w, {shape.wall[0], shape.wall[1]}),
      gravity_(c.gravity),
      drag_(drag_coefficients(c.zeta / shape.n_v, c.drag_rate, {shape.vertex_mass[0], shape.vertex_mass[1]})),
      corners_(hopper, p, shape, c.E_w),
      hopper_(hopper),
      cores_(hopper, shape.wall_thickness) {
  edge_widths_ = {shape.delta[0], shape.delta[1]};
  if (shape.smooth) {
    // Edges of one polygon repel its own vertices too (self-contact; not ring neighbours, whose
    // edges meet at them): nothing else keeps a soft polygon (K_l ~ 1, K_b ~ 1e-2) from folding
    // through itself, and the area term cannot notice, as a tangled polygon can keep its signed
    // area. At rest vertices two apart lie beyond both ends of each other's edges, so this acts
    // only on a folding polygon. Not in the paper: docs/validation.md.
    list_.set_groups(&p.owner, &p.first, 1);
    smooth_ = std::make_unique<DpSmoothContact>(list_, p, shape, E_c, FrictionLaw{c.mu_normal(), c.mu_tangential()},
                                                c.dp.E_c_vertex);
  } else {
    // Rough: vertex disks of one polygon repel too, except neighbours along the ring (they
    // overlap by construction; the segment term holds them). At rest vertices two apart are
    // 2 l0 cos(pi/n_v) > l0 away, so this acts only on a polygon folding over itself, which soft
    // bending (K_b ~ 1e-2) otherwise lets happen. Not in the paper: docs/validation.md.
    list_.set_groups(&p.owner, &p.first, 1);
    rough_ = std::make_unique<SpContact<2>>(list_, E_c, FrictionLaw{c.mu_normal(), c.mu_tangential()});
    rough_->set_friction_groups(&p.owner);
    rough_core_ = std::make_unique<DpSmoothContact>(DpSmoothContact::rough_edge_core(list_, p, shape, E_c));
    rough_fold_ = std::make_unique<DpSmoothContact>(DpSmoothContact::rough_fold_barrier(list_, p, shape, E_c));
    // the core's edges are narrower than the disks the list is built for
    edge_widths_ = DpSmoothContact::core_widths(shape);
  }
  // Each vertex's list reach covers half the bound of its edges (edge_reach()). Until the
  // first compute() sees the edges: the floor of the large species, which covers near-regular
  // polygons of both species (lists built directly, as some tests do); topology_changed() sets it.
  topology_changed();
  list_.set_extra_reach(&vertex_reach_);
  corner_edges_.reserve(p.vertices());
  fold_vertices_.reserve(p.vertices());
  for (int k = 0; k < 2; ++k) {
    lane_constants_.a0[k] = shape.a0[k];
    lane_constants_.K_a[k] = area_.stiffness(k);
    lane_constants_.K_l[k] = segments_.stiffness(k);
    lane_constants_.l0[k] = shape.l0[k];
    lane_constants_.bend_c[k] = bending_.edge_constant(k);
  }
  lane_constants_.bending = bending_.active();
  lanes_ = avx2::available();
  // a wall contact wider than the pair contact (dp.wall_width): the wall masks reach as far
  if (c.dp.wall_width) list_.set_wall_diameters({shape.wall[0], shape.wall[1]});
  if (shape.wall_thickness > 0) {
    // thick funnel walls: the masks reach the cores, which lie up to offset_from_wall() behind
    // the walls' segments, plus the walls' half thickness
    const double extra = 2 * (cores_.half_thickness() + cores_.offset_from_wall());
    list_.set_wall_diameters({shape.wall[0] + extra, shape.wall[1] + extra});
    // and they take every vertex a side wall's half-space acts on, at any distance beyond it
    list_.set_walls_acting_beyond(
        [this](const Vec<2>& x, double reach) { return cores_.walls_acting_beyond(x, reach); });
    walls_.set_funnel_cores(&cores_);
    corners_.set_funnel_cores(cores_);
  }
}

double DpForceField::edge_reach(double half_bound) const {
  // A vertex b within the width w_ab of edge a -> next(a), with a the edge's nearer end, is
  // within sqrt(w_ab^2 + |edge|^2 / 4) of a: the foot of its perpendicular (or, past the end,
  // the corner a itself) is at most |edge|/2 from a along the edge, and b at most w_ab from
  // it across (the contact's row test uses the same bound). The list already reaches the
  // pair's diameter d_ab; the extra covers the rest, for the species pair that needs most.
  double extra = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double w = 0.5 * (edge_widths_[a] + edge_widths_[b]);
      const double d = 0.5 * (shape_.delta[a] + shape_.delta[b]);
      extra = std::max(extra, std::sqrt(w * w + half_bound * half_bound) - d);
    }
  return extra;
}

void DpForceField::topology_changed() {
  edge_bound_.assign(poly_.vertices(), kEdgeBoundFloor * shape_.l0[1]);
  vertex_reach_.assign(poly_.vertices(), edge_reach(0.5 * kEdgeBoundFloor * shape_.l0[1]));
  list_.invalidate();
}

void DpForceField::set_shape_lanes(bool on) { lanes_ = on && avx2::available(); }

void DpForceField::set_threads(int threads) {
  threads_ = threads < 1 ? 1 : threads;
  if (smooth_) smooth_->set_threads(threads_);
  if (rough_core_) rough_core_->set_threads(threads_);  // the rough disks and fold barrier: one thread
}

ForceReport DpForceField::shape_list_and_contact(ParticleState<2>& s, bool energies, std::optional<double> max_moved2) {
  for (auto& fi : s.f) fi.setZero();
  ForceReport r;
  r.U_shape = shape_pass(s, energies);
  // The list must reach every edge of this very step: soft segments (K_l ~ 1) stretch edges to
  // several l0, and a list that does not follow misses contacts and lets vertices through edges.
  if (edge_outgrown_) reset_edge_bounds(s);
  if (!max_moved2)
    list_.update(s, hopper_);
  else if (list_.due(*max_moved2))  // a reinjection since the drift reset its vertices' references: still due if measured so
    list_.build(s, hopper_);
  if (smooth_) {
    const TermOutput o = smooth_->accumulate_with_folds(s, s.f, fold_vertices_);
    r.U_contact = o.energy;
    r.P_friction = o.power;
    r.max_overlap = smooth_->max_overlap();
  } else {
    const TermOutput o = rough_->accumulate(s, s.f);
    r.U_contact = o.energy + rough_core_->accumulate(s, s.f).energy +
                  rough_fold_->accumulate_with_folds(s, s.f, fold_vertices_).energy;
    r.P_friction = o.power;
    r.max_overlap = std::max({rough_->max_overlap(), rough_core_->max_overlap(), rough_fold_->max_overlap()});
  }
  return r;
}

ForceReport DpForceField::compute(ParticleState<2>& s) {
  ForceReport r = shape_list_and_contact(s, true);
  add_vertex_terms(s, r, 0.0, true);
  return r;
}

ForceReport DpForceField::compute_and_kick(ParticleState<2>& s, double dt, bool& finite,
                                           std::optional<double> max_moved2) {
  ForceReport r = shape_list_and_contact(s, false, max_moved2);
  finite = add_vertex_terms(s, r, 0.5 * dt, false);
  ForceReport out;  // the forces' by-products only: no energies, no powers
  out.max_overlap = r.max_overlap;
  return out;
}

namespace {
// The polygon's shape forces (its area, segment and bending results in `edges`) written to its
// vertices, each vertex's sum in the order of the terms one after another: area, then the
// segments of its edges in edge order, then bending likewise. For vertex k > 0 that is edge
// k - 1 (it is its end), then edge k (its start); for vertex 0, edge 0, then edge n - 1. The
// vertices' forces are zero before (compute() zeroes them and the polygon is its own).
void write_shape_forces(const PolygonEdges& edges, bool bending, VecArray<2>& f) {
  const int n = edges.count;
  const double* ax = edges.area_fx;
  const double* ay = edges.area_fy;
  const double* sx = edges.seg_fx;
  const double* sy = edges.seg_fy;
  const double* bx = edges.bend_dx;
  const double* by = edges.bend_dy;
  double* __restrict out = f[edges.first].data();  // x0, y0, x1, y1, ...: Vec<2> is two doubles
  static_assert(sizeof(Vec<2>) == 2 * sizeof(double));
  if (bending) {
    out[0] = (((0.0 + ax[0]) - sx[0]) + sx[n - 1]) + bx[0] - bx[n - 1];
    out[1] = (((0.0 + ay[0]) - sy[0]) + sy[n - 1]) + by[0] - by[n - 1];
    for (int k = 1; k < n; ++k) {
      out[2 * k] = ((((0.0 + ax[k]) + sx[k - 1]) - sx[k]) - bx[k - 1]) + bx[k];
      out[2 * k + 1] = ((((0.0 + ay[k]) + sy[k - 1]) - sy[k]) - by[k - 1]) + by[k];
    }
  } else {
    out[0] = ((0.0 + ax[0]) - sx[0]) + sx[n - 1];
    out[1] = ((0.0 + ay[0]) - sy[0]) + sy[n - 1];
    for (int k = 1; k < n; ++k) {
      out[2 * k] = ((0.0 + ax[k]) + sx[k - 1]) - sx[k];
      out[2 * k + 1] = ((0.0 + ay[k]) + sy[k - 1]) - sy[k];
    }
  }
}

// One term over vertices [begin, end): its force into f, its energy (or power) summed. Plain
// functions of a const state and a separate force array, as the terms' own accumulate(): with
// the state and its forces behind one non-const reference (a lambda capturing them) GCC
// reloaded per vertex what these keep in registers (the vertex terms took twice the time).
template <class Term>
double add_range(const Term& term, const ParticleState<2>& s, VecArray<2>& f, int begin, int end) {
  double sum = 0;
  for (int i = begin; i < end; ++i) sum += term.add_to(s, i, f[i]);
  return sum;
}
}  // namespace

namespace {
// What gravity_drag_kick() needs, as plain values and restrict pointers: through the state and
// the terms (references the force stores might alias) GCC reloaded every array pointer on
// every vertex, which made a fused sweep slower than three plain ones.
struct VertexTail {
  const double* __restrict X;
  double* __restrict V;
  double* __restrict F;
  const double* __restrict inv_m;
  const std::uint8_t* __restrict species;
  const std::uint8_t* __restrict waits;  ///< 1: the force and kick wait for the corners
  double mass[2], drag[2], g, half_dt;
};

// Vertices [begin, end): gravity's energy and drag's power summed in vertex order; but where
// a vertex waits for the corners, gravity's force -m g e_y, drag's -c v and the kick
// v += f dt / (2 m): Gravity::add_to's and Drag::add_to's operations, then kick_one's. Returns
// whether a kicked position or velocity is not finite.
template <bool kGravity, bool kDrag, bool kKick, bool kEnergy>
int gravity_drag_kick(int begin, int end, const VertexTail k, double& U_gravity, double& P_drag) {
  double U = 0, P = 0;
  int bad = 0;
  for (int i = begin; i < end; ++i) {
    const int sp = k.species[i];
    const double m = k.mass[sp], c = k.drag[sp];
    const __m128d v = _mm_loadu_pd(k.V + 2 * i);
    const double vx = _mm_cvtsd_f64(v), vy = _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
    if (kGravity && kEnergy) U += m * k.g * k.X[2 * i + 1];
    if (kDrag && kEnergy) P += -c * (vx * vx + vy * vy);
    if (k.waits[i]) continue;
    // the force as one 16-byte vector: two 8-byte stores read back as one would miss the
    // store forwarding (measured: the sweep took a third of the step); x - 0 is x, so the
    // force's x takes gravity's zero unchanged
    __m128d f = _mm_loadu_pd(k.F + 2 * i);
    if (kGravity) f = _mm_sub_pd(f, _mm_set_pd(m * k.g, 0.0));
    if (kDrag) f = _mm_sub_pd(f, _mm_mul_pd(_mm_set1_pd(c), v));
    _mm_storeu_pd(k.F + 2 * i, f);
    if (kKick) {  // kick_one()'s operations, on the force in hand
      const __m128d v_new = _mm_add_pd(v, _mm_mul_pd(_mm_set1_pd(k.half_dt * k.inv_m[i]), f));
      _mm_storeu_pd(k.V + 2 * i, v_new);
      const __m128d xv = _mm_add_pd(_mm_loadu_pd(k.X + 2 * i), v_new);
      bad |= not_finite(_mm_cvtsd_f64(xv) + _mm_cvtsd_f64(_mm_unpackhi_pd(xv, xv)));
    }
  }
  U_gravity = U;
  P_drag = P;
  return bad;
}

using TailSweep = int (*)(int, int, const VertexTail, double&, double&);
template <bool G, bool D>
TailSweep tail_sweep(bool kick, bool energy) {
  if (energy) return kick ? &gravity_drag_kick<G, D, true, true> : &gravity_drag_kick<G, D, false, true>;
  return kick ? &gravity_drag_kick<G, D, true, false> : &gravity_drag_kick<G, D, false, false>;
}
}  // namespace

bool DpForceField::add_vertex_terms(ParticleState<2>& s, ForceReport& r, double half_dt, bool energies) {
  // Each vertex takes the walls' force, then the corners' (edges near the orifice, few: in
  // order, one thread), then gravity, then drag: the order of the terms one after another. The
  // walls go in a sweep of their own, then gravity, drag and the kick in one more; the few
  // vertices a corner may touch (the ends of corner_edges_) take their gravity, drag and kick
  // after the corners. The energies and powers are summed in vertex order either way (they do
  // not depend on the force).
  const int n = s.size(), chunks = (n + kVerticesPerChunk - 1) / kVerticesPerChunk;
  if (static_cast<int>(chunk_sums_.size()) < 3 * chunks) {  // only when N grows
    chunk_sums_.resize(3 * chunks);
    chunk_bad_.resize(chunks);
  }
  if (static_cast<int>(waits_for_corners_.size()) < n) waits_for_corners_.resize(n, 0);
  std::uint8_t* waits = waits_for_corners_.data();
  for (const int e : corner_edges_) waits[e] = waits[poly_.next[e]] = 1;
  double* sums = chunk_sums_.data();
  int* bad = chunk_bad_.data();
  const ParticleState<2>& state = s;
  VecArray<2>& f = s.f;
  const bool gravity = gravity_.g() != 0, drag = drag_.active(), kick = half_dt > 0;
  for_chunks(chunks, [&, sums](int c) {
    const int begin = c * kVerticesPerChunk, end = std::min(n, begin + kVerticesPerChunk);
    if (energies) {
      sums[c] = add_range(walls_, state, f, begin, end);
    } else {  // no running sum: most vertices have no wall in reach and cost one test
      for (int i = begin; i < end; ++i)
        if (list_.wall_mask(i)) (void)walls_.add_to(state, i, f[i]);
      sums[c] = 0;
    }
  });
  const VertexTail tail{s.x.data()->data(), s.v.data()->data(), s.f.data()->data(), s.inv_mass.data(),
                        s.species.data(), waits, {s.sp.mass[0], s.sp.mass[1]},
                        {drag ? drag_.coefficient(0) : 0.0, drag ? drag_.coefficient(1) : 0.0}, gravity_.g(), half_dt};
  const bool e = energies;
  const TailSweep sweep = gravity ? (drag ? tail_sweep<true, true>(kick, e) : tail_sweep<true, false>(kick, e))
                                  : (drag ? tail_sweep<false, true>(kick, e) : tail_sweep<false, false>(kick, e));
  for_chunks(chunks, [&, sums, bad, sweep](int c) {
    const int begin = c * kVerticesPerChunk, end = std::min(n, begin + kVerticesPerChunk);
    bad[c] = sweep(begin, end, tail, sums[chunks + c], sums[2 * chunks + c]);
  });
  int not_finite_seen = 0;
  for (int c = 0; c < chunks; ++c) {
    r.U_wall += sums[c];
    not_finite_seen |= bad[c];
  }
  r.U_wall += corners_.accumulate_edges(s, s.f, corner_edges_).energy;
  for (const int e : corner_edges_) {
    for (const int i : {e, poly_.next[e]}) {
      if (!waits[i]) continue;  // the end of an earlier corner edge: done
      waits[i] = 0;
      if (gravity) gravity_.add_force(state, i, f[i]);
      if (drag) drag_.add_force(state, i, f[i]);
      if (kick) not_finite_seen |= not_finite(kick_one<2>(i, tail.X, tail.V, tail.F, half_dt, tail.inv_m));
    }
  }
  for (int c = 0; c < chunks; ++c) {
    r.U_gravity += sums[chunks + c];
    r.P_drag += sums[2 * chunks + c];
  }
  return not_finite_seen == 0;
}

// One chunk of polygons of the shape pass. (Compiled also for AVX2 with target_clones it ran
// 0.8 times as fast on case g: with 16 edges a polygon, 4-wide loops are mostly prologue.)
void DpForceField::shape_chunk(ParticleState<2>& s, int c, bool energies) {
  const int np = poly_.polygons();
  ShapeChunk& ch = shape_chunks_[c];
  ch.corner_edges.clear();
  ch.fold_vertices.clear();
  PolygonEdges& edges = ch.edges;
  // the sums in locals (kept in registers: the chunk's members could alias the force stores)
  double U_area = 0, U_length = 0, U_bending = 0, longest = 0;
  bool outgrown = false;
  for (int m = c * kPolygonsPerChunk, end = std::min(np, (c + 1) * kPolygonsPerChunk); m < end; ++m) {
    if (lanes_ && m + 4 <= end) {  // four polygons at once, in polygon order for every sum and list
      double sums[3] = {U_area, U_length, U_bending};
      shape_four(s, m, ch, energies, sums, longest, outgrown);
      U_area = sums[0];
      U_length = sums[1];
      U_bending = sums[2];
      m += 3;
      continue;
    }
    edges.measure(poly_, s, m);
    U_area += area_.vertex_forces(edges);
    segments_.edge_forces(edges);
    if (bending_.active()) bending_.edge_gradients(edges);
    write_shape_forces(edges, bending_.active(), s.f);
    if (energies) {
      for (int k = 0; k < edges.count; ++k) U_length += edges.seg_u[k];
      for (int k = 0; bending_.active() && k < edges.count; ++k) U_bending += edges.bend_u[k];
    }
    const int n = edges.count;
    // Straight loops without an order-dependent sum (vectorised): the perimeter is only a bound
    // for the corner test below, so its order of summation is free; the longest edge is a
    // maximum (any order, the same value); an edge outgrew its bound: an or.
    double perimeter = 0, polygon_longest = 0;
    int grown = 0;
    {
      const double* __restrict sq = edges.sq;
      const double* __restrict len = edges.len;
      const double* __restrict bound = edge_bound_.data() + edges.first;
      #pragma omp simd reduction(+ : perimeter) reduction(max : polygon_longest) reduction(| : grown)
      for (int k = 0; k < n; ++k) {
        grown |= sq[k] > bound[k] * bound[k];
        perimeter += len[k];
        polygon_longest = len[k] > polygon_longest ? len[k] : polygon_longest;
      }
    }
    outgrown = outgrown || grown;
    longest = polygon_longest > longest ? polygon_longest : longest;
    // the fold pairs (of the smooth contact, or the rough model's fold barrier) act only where
    // the polygon folds (at rest: nowhere): one vectorised test for the polygon (vertex k's
    // edges are k - 1 and k; edge -1 is the last), then vertex by vertex where it says so
    const DpSmoothContact* folds = smooth_ ? smooth_.get() : rough_fold_.get();
    int may_fold = 0;
    if (folds->has_folds()) {
      const double w2 = folds->fold_width2(edges.species);
      const double* __restrict ex = edges.ex;
      const double* __restrict ey = edges.ey;
      const double* __restrict sq = edges.sq;
      #pragma omp simd reduction(| : may_fold)
      for (int k = 0; k < n; ++k)  // fold_may_act()'s test, & for && (no branch; the same for NaN)
        may_fold |= !((ex[k - 1] * ex[k] + ey[k - 1] * ey[k] > 0) & (sq[k - 1] >= w2) & (sq[k] >= w2));
    }
    for (int k = 0; may_fold && k < n; ++k) {
      const int i = edges.first + k, in = poly_.prev[i] - edges.first;
      if (folds->fold_may_act(edges.dot(in, k), edges.sq[in], edges.sq[k], edges.species))
        ch.fold_vertices.push_back(i);  // grows to its largest once, then no allocation
    }
    // most polygons are far from the orifice: one test for the polygon, then one per edge
    if (!corners_.polygon_may_touch(s, edges.first, perimeter)) continue;
    for (int k = 0; k < n; ++k)
      if (corners_.may_touch(s, edges.first + k, edges.sq[k])) ch.corner_edges.push_back(edges.first + k);
  }
  ch.U_area = U_area;
  ch.U_length = U_length;
  ch.U_bending = U_bending;
  ch.longest = longest;
  ch.outgrown = outgrown;
}

void DpForceField::shape_four(ParticleState<2>& s, int m, ShapeChunk& ch, bool energies, double sums[3], double& longest,
                              bool& outgrown) {
  int first[4], sp[4];
  const int n = poly_.first[m + 1] - poly_.first[m];
  for (int j = 0; j < 4; ++j) {
    first[j] = poly_.first[m + j];
    sp[j] = s.species[first[j]];
  }
  const DpSmoothContact* folds = smooth_ ? smooth_.get() : rough_fold_.get();
  const double fold_w2[2] = {folds->fold_width2(0), folds->fold_width2(1)};
  avx2::ShapeLanes& L = ch.lanes;
  L.run(s.x.data()->data(), s.f.data()->data(), first, sp, n, lane_constants_, edge_bound_.data(), folds->has_folds(),
        fold_w2, energies);
  outgrown = outgrown || L.grown;
  longest = L.longest > longest ? L.longest : longest;
  const double* sq = L.sq();
  for (int j = 0; j < 4; ++j) {  // polygon m + j: what the one-polygon path does after its forces
    if (energies) {
      sums[0] += L.U_area[j];
      for (int k = 0; k < n; ++k) sums[1] += L.seg_u()[4 * k + j];
      for (int k = 0; lane_constants_.bending && k < n; ++k) sums[2] += L.bend_u()[4 * k + j];
    }
    for (int k = 0; (L.may_fold >> j & 1) && k < n; ++k) {
      const int in = k == 0 ? n - 1 : k - 1;  // polygons are contiguous and cyclic
      const double dot = L.ex()[4 * in + j] * L.ex()[4 * k + j] + L.ey()[4 * in + j] * L.ey()[4 * k + j];
      if (folds->fold_may_act(dot, sq[4 * in + j], sq[4 * k + j], sp[j])) ch.fold_vertices.push_back(first[j] + k);
    }
    if (!corners_.polygon_may_touch(s, first[j], L.perimeter[j])) continue;
    for (int k = 0; k < n; ++k)
      if (corners_.may_touch(s, first[j] + k, sq[4 * k + j])) ch.corner_edges.push_back(first[j] + k);
  }
}

double DpForceField::shape_pass(ParticleState<2>& s, bool energies) {
  // Each vertex's force takes contributions of its own polygon's shape terms only, so polygon
  // by polygon (area, then segments, then bending within each) it sums the same numbers in the
  // same order as the three terms one after another over all polygons: the same forces, with
  // one pass over the positions and one square root per edge instead of two
  // (tests/physics/test_dp_forces.cpp, FusedShapePassEqualsTheTermsOneAfterAnother). Polygons
  // go in fixed chunks (any thread count: the same chunks, their sums in chunk order).
  const int np = poly_.polygons(), chunks = (np + kPolygonsPerChunk - 1) / kPolygonsPerChunk;
  if (static_cast<int>(shape_chunks_.size()) < chunks) shape_chunks_.resize(chunks);  // only when N grows
  for_chunks(chunks, [&](int c) { shape_chunk(s, c, energies); });
  double U_area = 0, U_length = 0, U_bending = 0, longest = 0;
  bool outgrown = false;
  corner_edges_.clear();
  fold_vertices_.clear();
  for (int c = 0; c < chunks; ++c) {  // in chunk order: the lists stay increasing
    const ShapeChunk& ch = shape_chunks_[c];
    U_area += ch.U_area;
    U_length += ch.U_length;
    U_bending += ch.U_bending;
    longest = std::max(longest, ch.longest);
    outgrown = outgrown || ch.outgrown;
    corner_edges_.insert(corner_edges_.end(), ch.corner_edges.begin(), ch.corner_edges.end());  // capacity reserved
    fold_vertices_.insert(fold_vertices_.end(), ch.fold_vertices.begin(), ch.fold_vertices.end());
  }
  segments_.set_longest_edge(longest);
  edge_outgrown_ = outgrown;
  return U_area + U_length + U_bending;
}

void DpForceField::reset_edge_bounds(const ParticleState<2>& s) {
  // Every bound (not only the outgrown one), so that bounds also shrink back after a stretched
  // polygon relaxes; this happens rarely, and it costs one list rebuild.
  const int n = poly_.vertices();
  for (int i = 0; i < n; ++i) {
    const double len = (s.x[poly_.next[i]] - s.x[i]).norm();
    edge_bound_[i] = std::max(kEdgeBoundGrowth * len, kEdgeBoundFloor * shape_.l0[s.species[i]]);
  }
  for (int i = 0; i < n; ++i)
    vertex_reach_[i] = edge_reach(0.5 * std::max(edge_bound_[i], edge_bound_[poly_.prev[i]]));
  list_.invalidate();
}

void DpForceField::set_dissipation(bool on) {
  if (smooth_) smooth_->set_friction_enabled(on);
  if (rough_) rough_->set_friction_enabled(on);
  drag_.set_enabled(on);
}

void DpForceField::friction_forces(const ParticleState<2>& s, VecArray<2>& out) const {
  if (smooth_)
    smooth_->friction_forces(s, out);
  else
    rough_->friction_forces(s, out);
}

std::string DpForceField::describe_worst_contact(const ParticleState<2>& s, const PolygonSet& p) const {
  // the smooth contact, or the rough edge core or fold barrier if its overlap is the larger
  // (rough disks: no detail)
  const DpSmoothContact* edges = smooth_.get();
  if (!smooth_) {
    edges = rough_fold_->max_overlap() > rough_core_->max_overlap() ? rough_fold_.get() : rough_core_.get();
    if (edges->max_overlap() < rough_->max_overlap()) return "";
  }
  const auto [vertex, edge] = edges->worst_contact();
  if (vertex < 0) return "";
  std::ostringstream m;
  m << " (vertex " << vertex << " of polygon " << p.owner[vertex] << " at " << s.x[vertex].transpose() << " against the edge from vertex "
    << edge << " of polygon " << p.owner[edge] << ")";
  return m.str();
}

std::vector<ForceTerm<2>*> DpForceField::terms() {
  if (smooth_) return {&area_, &segments_, &bending_, smooth_.get(), &walls_, &gravity_, &drag_, &corners_};
  return {&area_, &segments_, &bending_, rough_.get(), &walls_, &gravity_, &drag_, &corners_, rough_core_.get(), rough_fold_.get()};
}

}  // namespace beverloo
