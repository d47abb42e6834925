#include "dp_model.h"

#include <optional>

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "../forces/harmonic_overlap.h"
#include "../io/vec_io.h"
#include "../units.h"

namespace beverloo {

TimeScales DpModel::time_scales(const SimConfig& c) {
  // Per vertex (mass M/n_v); the contact acts on the reduced mass of two vertices.
  const DpShape shape = DpShape::from_config(c);
  const char* names[2] = {"small", "large"};
  const double mu_max = std::max(c.mu_normal(), c.mu_tangential());  // the stronger friction
  const double nv = shape.n_v;
  TimeScales s;
  for (int a = 0; a < 2; ++a) {
    const double mv = shape.vertex_mass[a], l0 = shape.l0[a];
    for (int b = a; b < 2; ++b) {
      const double m_red = mv * shape.vertex_mass[b] / (mv + shape.vertex_mass[b]);
      const double delta = 0.5 * (shape.delta[a] + shape.delta[b]);
      const std::string pair = std::string(names[a]) + "-" + names[b];
      s.oscillation(m_red, HarmonicOverlap::stiffness(std::max(c.dp.E_c, c.dp.E_c_vertex.value_or(0)), delta),
                    "dp.E_c (" + pair + " vertex contact)");
      if (mu_max > 0) s.damping(m_red / mu_max, "mu (kinetic friction, " + pair + " vertices)");
    }
    const std::string who = std::string(names[a]) + " vertex";
    s.oscillation(mv, HarmonicOverlap::stiffness(c.E_w, 0.5 * shape.wall[a]), "E_w (wall, " + who + ")");
    // edge spring K_l n_v between two vertices; area: |grad a|^2 ~ l0^2 per vertex;
    // bending: moving one vertex by x turns three edge pairs, curvature 6 K_b/(n_v l0^4)
    s.oscillation(0.5 * mv, c.dp.K_l_of(a) * nv, std::string(a && c.dp.K_l_large ? "dp.K_l_large" : "dp.K_l") + " (segment length, " + who + ")");
    s.oscillation(mv, c.dp.K_a_of(a) * l0 * l0, std::string(a && c.dp.K_a_large ? "dp.K_a_large" : "dp.K_a") + " (area, " + who + ")");
    if (c.dp.K_b > 0) s.oscillation(mv, 6 * c.dp.K_b / (nv * l0 * l0 * l0 * l0), "dp.K_b (bending, " + who + ")");
    if (c.zeta > 0 || c.drag_rate > 0)
      s.damping(mv / (c.zeta / nv + c.drag_rate * mv), std::string(c.drag_rate > 0 ? "zeta, drag_rate" : "zeta") + " (drag, " + who + ")");
  }
  return s;
}

void DpModel::place(ParticleState<2>& bodies, Rng& rng) {
  dp_.place_bodies(bodies, rng);
  dp_.build_polygons(bodies, rng);
}

FireResult DpModel::minimize(ParticleState<2>& bodies, double dt) {
  const FireResult r = dp_.minimize(c_.fire, dt);
  dp_.sync_bodies(bodies);
  return r;
}

void DpModel::start_flow(ParticleState<2>& bodies) {
  dp_.verts().step = bodies.step;
  DpForceField& f = dp_.forces();
  f.set_gravity(c_.gravity);
  f.set_dissipation(true);
  f.list().invalidate();
  bodies_list_.invalidate();
  // as for SP: the forces of the resumed state equal those of the uninterrupted run
  if (bodies.step == 0) f.compute(dp_.verts());
}

StepReport DpModel::step(ParticleState<2>& bodies, double dt, StepHook<2>& hook) {
  // velocity_verlet_step() with its closing kick taken in the force field's last sweep
  // (DpForceField::compute_and_kick): the same operations, the same bits
  static const VecArray<2> kNoReference;
  ParticleState<2>& verts = dp_.verts();
  DpForceField& forces = dp_.forces();
  std::optional<double> max_moved2;  // the list's displacement test, where the drift's pass took it
  if (forces.threads() == 1) {
    const double moved2 = dp_.drift_and_sync(bodies, dt, forces.list().reference_positions());
    if (moved2 >= 0) max_moved2 = moved2;
  } else {
    drift(verts, dt, kNoReference, forces.threads());
    dp_.sync_bodies(bodies);
  }
  // exits are counted when the centroid crosses the orifice
  hook.between_drift_and_force(bodies, bodies_list_, true);
  StepReport r;
  r.forces = forces.compute_and_kick(verts, dt, r.finite, max_moved2);
  ++verts.step;
  bodies.step = verts.step;
  dp_.sync_bodies(bodies);
  return r;
}

void DpModel::check_step(const StepReport& r, double t, double max_overlap) const {
  if (!r.finite) throw InstabilityError("NaN or infinite vertex position/velocity at t = " + std::to_string(t));
  if (r.forces.max_overlap > max_overlap) {
    throw InstabilityError("contact overlap 1 - d/delta = " + std::to_string(r.forces.max_overlap) +
                           " beyond max_overlap = " + std::to_string(max_overlap) + " at t = " + std::to_string(t) +
                           dp_.forces().describe_worst_contact(dp_.verts(), dp_.polygons()));
  }
}

void DpModel::reinjected(int i, ParticleState<2>& bodies, Rng& rng) {
  dp_.reinject(i, bodies.x[i], bodies.v[i], rng.uniform(0, 2 * units::pi));
}

void DpModel::copy_state_from(const HopperModel<2>& other) {
  dp_.verts() = static_cast<const DpModel&>(other).dp_.verts();
  dp_.forces().list().invalidate();
  bodies_list_.invalidate();
}

void DpModel::save_checkpoint(hid_t file) const {
  // the vertices are the state; the bodies beside them are their centroids
  const ParticleState<2>& vs = dp_.verts();
  H5Handle vg = h5::create_group(file, "vertices");
  h5::write(vg, "x", flatten<2>(vs.x), {hsize_t(vs.size()), hsize_t(2)});
  h5::write(vg, "v", flatten<2>(vs.v), {hsize_t(vs.size()), hsize_t(2)});
  h5::write(vg, "f", flatten<2>(vs.f), {hsize_t(vs.size()), hsize_t(2)});
}

void DpModel::load_checkpoint(hid_t file, ParticleState<2>& bodies) {
  dp_.keep_polygons(bodies.size());  // a draining hopper's checkpoint holds fewer than N
  ParticleState<2>& vs = dp_.verts();
  const PolygonSet& poly = dp_.polygons();
  for (int i = 0; i < vs.size(); ++i) {
    vs.species[i] = bodies.species[poly.owner[i]];
    vs.inv_mass[i] = 1.0 / vs.sp.mass[vs.species[i]];
  }
  H5Handle vg = h5::open_group(file, "vertices");
  unflatten<2>(h5::read_doubles(vg, "x"), vs.x, "vertices/x");
  unflatten<2>(h5::read_doubles(vg, "v"), vs.v, "vertices/v");
  unflatten<2>(h5::read_doubles(vg, "f"), vs.f, "vertices/f");
  dp_.sync_bodies(bodies);
}

}  // namespace beverloo
