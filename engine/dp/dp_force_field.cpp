#include "dp_force_field.h"

#include <sstream>

namespace beverloo {

std::array<double, 2> DpForceField::list_diameters(const DpShape& shape) {
  if (!shape.smooth) return {shape.delta[0], shape.delta[1]};  // vertex disks: contact = reach
  // a vertex within delta_mn of an edge is within max_edge + delta_mn of the edge's start
  return {shape.max_edge + shape.delta[0], shape.max_edge + shape.delta[1]};
}

DpForceField::DpForceField(const SimConfig& c, const Hopper<2>& hopper, const PolygonSet& p, const DpShape& shape,
                           double E_c)
    : shape_(shape),
      edge_reach_(shape.max_edge),
      list_(c.skin),
      area_(p, shape, c.dp.K_a),
      segments_(p, shape, c.dp.K_l),
      bending_(p, shape, c.dp.K_b),
      walls_(hopper, list_, c.E_w, {shape.delta[0], shape.delta[1]}),
      gravity_(c.gravity),
      drag_(c.zeta / shape.n_v),
      corners_(hopper, p, shape, c.E_w),
      hopper_(hopper) {
  if (shape.smooth) {
    list_.set_groups(&p.owner);
    smooth_ = std::make_unique<DpSmoothContact>(list_, p, shape, E_c, c.mu);
  } else {
    // Rough: vertex disks of one polygon repel too, except neighbours along the ring (they
    // overlap by construction; the segment term holds them). At rest vertices two apart are
    // 2 l0 cos(pi/n_v) > l0 away, so this acts only on a polygon folding over itself, which soft
    // bending (K_b ~ 1e-2) otherwise lets happen. Not in the paper: docs/validation.md.
    list_.set_groups(&p.owner, &p.first, 1);
    rough_ = std::make_unique<SpContact<2>>(list_, E_c, c.mu);
  }
}

ForceReport DpForceField::compute(ParticleState<2>& s) {
  for (auto& fi : s.f) fi.setZero();
  ForceReport r;
  r.U_shape = area_.accumulate(s, s.f).energy + segments_.accumulate(s, s.f).energy + bending_.accumulate(s, s.f).energy;
  // A vertex within delta of an edge is within |edge| + delta of the edge's start vertex: the
  // list must reach that far for the longest edge of this very step. Soft segments (K_l ~ 1)
  // stretch edges to several l0; a list that does not follow misses contacts and lets vertices
  // through edges.
  if (smooth_ && segments_.longest_edge() > edge_reach_) {
    edge_reach_ = 1.25 * segments_.longest_edge();
    s.sp.sigma = {edge_reach_ + shape_.delta[0], edge_reach_ + shape_.delta[1]};
    list_.invalidate();
  }
  list_.update(s, hopper_);
  if (smooth_) {
    const TermOutput o = smooth_->accumulate(s, s.f);
    r.U_contact = o.energy;
    r.P_friction = o.power;
    r.max_overlap = smooth_->max_overlap();
  } else {
    const TermOutput o = rough_->accumulate(s, s.f);
    r.U_contact = o.energy;
    r.P_friction = o.power;
    r.max_overlap = rough_->max_overlap();
  }
  r.U_wall = walls_.accumulate(s, s.f).energy;
  r.U_wall += corners_.accumulate(s, s.f).energy;
  r.U_gravity = gravity_.accumulate(s, s.f).energy;
  r.P_drag = drag_.accumulate(s, s.f).power;
  return r;
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
  if (!smooth_) return "";
  const auto [vertex, edge] = smooth_->worst_contact();
  if (vertex < 0) return "";
  std::ostringstream m;
  m << " (vertex " << vertex << " of polygon " << p.owner[vertex] << " at " << s.x[vertex].transpose() << " against the edge from vertex "
    << edge << " of polygon " << p.owner[edge] << ")";
  return m.str();
}

std::vector<ForceTerm<2>*> DpForceField::terms() {
  ForceTerm<2>* contact = smooth_ ? static_cast<ForceTerm<2>*>(smooth_.get()) : rough_.get();
  return {&area_, &segments_, &bending_, contact, &walls_, &gravity_, &drag_, &corners_};
}

}  // namespace beverloo
