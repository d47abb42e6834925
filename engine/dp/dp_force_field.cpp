#include "dp_force_field.h"

#include <algorithm>
#include <sstream>

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
    // the disks' list reach (l0) already covers a core contact within l0 - l0/2 of a vertex
    const auto core = DpSmoothContact::core_widths(shape);
    reach_covered_ = std::min(shape.delta[0] - core[0], shape.delta[1] - core[1]);
  }
  // A vertex within the edge width of an edge is within |edge|/2 of the edge's nearer end
  // vertex plus that width (the foot of the perpendicular, or the corner, is at most |edge|/2
  // from it): each vertex's list reach covers half the bound of its edges. Until the first
  // compute() sees the edges: the floor of the large species, which covers near-regular
  // polygons of both species (lists built directly, as some tests do).
  edge_bound_.assign(p.vertices(), kEdgeBoundFloor * shape.l0[1]);
  vertex_reach_.assign(p.vertices(), std::max(0.0, 0.5 * kEdgeBoundFloor * shape.l0[1] - reach_covered_));
  list_.set_extra_reach(&vertex_reach_);
  corner_edges_.reserve(p.vertices());
  fold_vertices_.reserve(p.vertices());
  // a wall contact wider than the pair contact (dp.wall_width): the wall masks reach as far
  if (c.dp.wall_width) list_.set_wall_diameters({shape.wall[0], shape.wall[1]});
  if (shape.wall_thickness > 0) {
    // thick funnel walls: the masks reach the cores, which lie up to offset_from_wall() behind
    // the walls' segments, plus the walls' half thickness
    const double extra = 2 * (cores_.half_thickness() + cores_.offset_from_wall());
    list_.set_wall_diameters({shape.wall[0] + extra, shape.wall[1] + extra});
    walls_.set_funnel_cores(&cores_);
    corners_.set_funnel_cores(cores_);
  }
}

void DpForceField::topology_changed() {
  edge_bound_.assign(poly_.vertices(), kEdgeBoundFloor * shape_.l0[1]);
  vertex_reach_.assign(poly_.vertices(), std::max(0.0, 0.5 * kEdgeBoundFloor * shape_.l0[1] - reach_covered_));
  list_.invalidate();
}

ForceReport DpForceField::compute(ParticleState<2>& s) {
  for (auto& fi : s.f) fi.setZero();
  ForceReport r;
  r.U_shape = shape_pass(s);
  // The list must reach every edge of this very step: soft segments (K_l ~ 1) stretch edges to
  // several l0, and a list that does not follow misses contacts and lets vertices through edges.
  if (edge_outgrown_) reset_edge_bounds(s);
  list_.update(s, hopper_);
  if (smooth_) {
    const TermOutput o = smooth_->accumulate_with_folds(s, s.f, fold_vertices_);
    r.U_contact = o.energy;
    r.P_friction = o.power;
    r.max_overlap = smooth_->max_overlap();
  } else {
    const TermOutput o = rough_->accumulate(s, s.f);
    r.U_contact = o.energy + rough_core_->accumulate(s, s.f).energy + rough_fold_->accumulate(s, s.f).energy;
    r.P_friction = o.power;
    r.max_overlap = std::max({rough_->max_overlap(), rough_core_->max_overlap(), rough_fold_->max_overlap()});
  }
  r.U_wall = walls_.accumulate(s, s.f).energy;
  r.U_wall += corners_.accumulate_edges(s, s.f, corner_edges_).energy;
  r.U_gravity = gravity_.accumulate(s, s.f).energy;
  r.P_drag = drag_.accumulate(s, s.f).power;
  return r;
}

double DpForceField::shape_pass(ParticleState<2>& s) {
  // Each vertex's force takes contributions of its own polygon's shape terms only, so polygon
  // by polygon (area, then segments, then bending within each) it sums the same numbers in the
  // same order as the three terms one after another over all polygons: the same bits, with
  // one pass over the positions and one square root per edge instead of two
  // (tests/physics/test_dp_forces.cpp, FusedShapePassEqualsTheTermsOneAfterAnother).
  double U_area = 0, U_length = 0, U_bending = 0, longest = 0;
  bool outgrown = false;
  corner_edges_.clear();
  fold_vertices_.clear();
  for (int m = 0; m < poly_.polygons(); ++m) {
    edges_.measure(poly_, s.x, m);
    area_.add_polygon(s, s.f, m, U_area);
    segments_.add_polygon(s, s.f, edges_, U_length, longest);
    bending_.add_polygon(s, s.f, edges_, U_bending);
    const int n = edges_.count;
    double perimeter = 0;
    for (int k = 0; k < n; ++k) {
      const int i = edges_.first + k;
      outgrown = outgrown || edges_.sq[k] > edge_bound_[i] * edge_bound_[i];
      perimeter += edges_.len[k];
    }
    // the smooth contact's fold pairs act only where the polygon folds (at rest: nowhere)
    for (int k = 0; smooth_ && k < n; ++k) {
      const int i = edges_.first + k, in = poly_.prev[i] - edges_.first;
      if (smooth_->fold_may_act(edges_.e[in].dot(edges_.e[k]), edges_.sq[in], edges_.sq[k], s.species[i]))
        fold_vertices_.push_back(i);  // capacity reserved: no allocation
    }
    // most polygons are far from the orifice: one test for the polygon, then one per edge
    if (!corners_.polygon_may_touch(s, edges_.first, perimeter)) continue;
    for (int k = 0; k < n; ++k)
      if (corners_.may_touch(s, edges_.first + k, edges_.sq[k]))
        corner_edges_.push_back(edges_.first + k);  // capacity reserved: no allocation
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
    vertex_reach_[i] = std::max(0.0, 0.5 * std::max(edge_bound_[i], edge_bound_[poly_.prev[i]]) - reach_covered_);
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
