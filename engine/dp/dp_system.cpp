#include "dp_system.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../integrate/velocity_verlet.h"
#include "../protocol/exit_counter.h"
#include "../units.h"

namespace beverloo {

DpSystem::DpSystem(const SimConfig& c, const Hopper<2>& hopper)
    : c_(c), hopper_(hopper), shape_(DpShape::from_config(c)), poly_(PolygonSet::uniform(c.N, c.dp.n_v)) {
  const auto diam = DpForceField::list_diameters(shape_);
  verts_.sp.sigma = {diam[0], diam[1]};
  verts_.sp.mass = {shape_.vertex_mass[0], shape_.vertex_mass[1]};
  verts_.sp.ref_size = {shape_.a0[0], shape_.a0[1]};
  verts_.resize(poly_.vertices());
  ff_ = std::make_unique<DpForceField>(c_, hopper_, poly_, shape_, c_.dp.E_c);
}

Species DpSystem::body_species() const {
  Species sp = Species::bidisperse(2, c_.size_ratio);
  for (int k = 0; k < 2; ++k) sp.sigma[k] = kBodyMargin * shape_.bounding_diameter(k);
  return sp;
}

void DpSystem::place_bodies(ParticleState<2>& bodies, Rng& rng) const {
  bodies.sp = body_species();
  bodies.resize(c_.N);
  std::vector<std::uint8_t> species(c_.N);
  for (int i = 0; i < c_.N; ++i) species[i] = i < c_.N / 2 ? 0 : 1;
  for (int i = c_.N - 1; i > 0; --i) {  // Fisher-Yates with our own generator (portable)
    const int j = static_cast<int>(rng.uniform() * (i + 1));
    std::swap(species[i], species[std::min(j, i)]);
  }
  const double spacing = bodies.sp.sigma[1] * 1.02, row = spacing * std::sqrt(3.0) / 2;
  const double half = hopper_.half_width() - 0.5 * spacing;
  // rows alternate by half a spacing; the shifted rows must fit too
  const int per_row = std::max(1, static_cast<int>(2 * half / spacing - 0.5) + 1);
  const double bottom = hopper_.funnel_top() + 0.5 * spacing;
  const double jitter = 0.01 * spacing;
  for (int i = 0; i < c_.N; ++i) {
    const int r = i / per_row, k = i % per_row;
    // (lateral_centre() is 0 unless a funnel wall is vertical: adding it changes no bit)
    const double x = hopper_.lateral_centre() + (-half + k * spacing + (r % 2 ? 0.5 * spacing : 0.0));
    bodies.x[i] = Vec<2>(x + jitter * rng.uniform(-1, 1), bottom + r * row + jitter * rng.uniform(-1, 1));
    bodies.species[i] = species[i];
    bodies.inv_mass[i] = 1.0 / bodies.sp.mass[species[i]];
  }
}

void DpSystem::build_polygons(const ParticleState<2>& bodies, Rng& rng) {
  for (int m = 0; m < c_.N; ++m) {
    for (int i = poly_.first[m]; i < poly_.first[m + 1]; ++i) {
      verts_.species[i] = bodies.species[m];
      verts_.inv_mass[i] = 1.0 / shape_.vertex_mass[bodies.species[m]];
    }
    place_regular_polygon(poly_, shape_, verts_, m, bodies.x[m], rng.uniform(0, 2 * units::pi), Vec<2>::Zero());
  }
  verts_.exited.assign(verts_.size(), 0);
}

FireResult DpSystem::minimize(const FireParams& p, double dt) {
  DpForceField soft(c_, hopper_, poly_, shape_, std::min(c_.dp.E_c, p.max_pair_stiffness));
  soft.set_gravity(0);
  soft.set_dissipation(false);
  return fire_minimize(verts_, soft, p, dt);
}

template <class Vertex>
void DpSystem::sum_polygons(ParticleState<2>& bodies, Vertex&& vertex) const {
  // Each centroid is a sum in vertex order (its bits are what exits, reinjection and the
  // observables see); a sum is a chain of dependent adds, so four polygons go side by side
  // (eight independent chains), each still summed in its own order. Polygons are uniform.
  const __m128d inv_nv = _mm_set1_pd(1.0 / c_.dp.n_v);
  const int np = poly_.polygons(), n = c_.dp.n_v;
  int m = 0;
  for (; m + 4 <= np; m += 4) {
    __m128d x[4], v[4];
    for (int j = 0; j < 4; ++j) x[j] = v[j] = _mm_setzero_pd();
    const int f = poly_.first[m];
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < 4; ++j) {
        __m128d xi, vi;
        vertex(f + j * n + k, xi, vi);
        x[j] = _mm_add_pd(x[j], xi);
        v[j] = _mm_add_pd(v[j], vi);
      }
    for (int j = 0; j < 4; ++j) {
      _mm_storeu_pd(bodies.x[m + j].data(), _mm_mul_pd(x[j], inv_nv));
      _mm_storeu_pd(bodies.v[m + j].data(), _mm_mul_pd(v[j], inv_nv));
    }
  }
  for (; m < np; ++m) {
    __m128d x = _mm_setzero_pd(), v = _mm_setzero_pd();
    for (int i = poly_.first[m]; i < poly_.first[m + 1]; ++i) {
      __m128d xi, vi;
      vertex(i, xi, vi);
      x = _mm_add_pd(x, xi);
      v = _mm_add_pd(v, vi);
    }
    _mm_storeu_pd(bodies.x[m].data(), _mm_mul_pd(x, inv_nv));
    _mm_storeu_pd(bodies.v[m].data(), _mm_mul_pd(v, inv_nv));
  }
}

void DpSystem::sync_bodies(ParticleState<2>& bodies) const {
  const double* X = verts_.x.data()->data();
  const double* V = verts_.v.data()->data();
  sum_polygons(bodies, [&](int i, __m128d& x, __m128d& v) __attribute__((always_inline)) {
    x = _mm_loadu_pd(X + 2 * i);
    v = _mm_loadu_pd(V + 2 * i);
  });
}

double DpSystem::drift_and_sync(ParticleState<2>& bodies, double dt, const VecArray<2>& reference) {
  const __m128d vdt = _mm_set1_pd(dt), vh = _mm_set1_pd(0.5 * dt), vh2 = _mm_set1_pd(0.5 * dt * dt);
  double* __restrict X = verts_.x.data()->data();
  double* __restrict V = verts_.v.data()->data();
  const double* __restrict F = verts_.f.data()->data();
  const double* __restrict inv_m = verts_.inv_mass.data();
  const bool measure = reference.size() == verts_.x.size();
  const double* __restrict R = measure ? reference.data()->data() : nullptr;
  __m128d moved2 = _mm_setzero_pd();  // the largest squared displacement, in the low lane
  sum_polygons(bodies, [&](int i, __m128d& x, __m128d& v) __attribute__((always_inline)) {
    drift_item_2d(i, X, V, F, inv_m, vdt, vh, vh2, x, v);
    if (measure) {  // (u_x^2 + u_y^2), as squaredNorm()
      const __m128d u = _mm_sub_pd(x, _mm_loadu_pd(R + 2 * i));
      const __m128d u2 = _mm_mul_pd(u, u);
      moved2 = _mm_max_sd(moved2, _mm_add_sd(u2, _mm_unpackhi_pd(u2, u2)));
    }
  });
  return measure ? _mm_cvtsd_f64(moved2) : -1.0;
}

void DpSystem::reinject(int m, const Vec<2>& centre, const Vec<2>& velocity, double angle) {
  place_regular_polygon(poly_, shape_, verts_, m, centre, angle, velocity);
  for (int i = poly_.first[m]; i < poly_.first[m + 1]; ++i) ff_->list().relocate(i, verts_, hopper_);
}

void DpSystem::remove_polygon(int m) {
  const int last = poly_.polygons() - 1, nv = shape_.n_v;
  for (int k = 0; k < nv; ++k) verts_.move(poly_.first[last] + k, poly_.first[m] + k);
  keep_polygons(last);
}

void DpSystem::keep_polygons(int n) {
  verts_.truncate(n * shape_.n_v);
  // the topology is uniform: rebuilt in place (the terms and the list hold references to it)
  poly_ = PolygonSet::uniform(n, shape_.n_v);
  ff_->topology_changed();
}

bool DpSystem::spot_is_free(int m, const Vec<2>& centre) const {
  // The regular polygon lies within its circumradius; its contact shell reaches delta/2
  // beyond (for rough disks, beyond its vertices), and the other polygon's shell as far.
  const int sm = verts_.species[poly_.first[m]];
  for (int i = 0; i < verts_.size(); ++i) {
    if (poly_.owner[i] == m) continue;
    const double reach = shape_.circumradius[sm] + 0.5 * (shape_.delta[sm] + shape_.delta[verts_.species[i]]);
    const Vec<2> a = verts_.x[i], e = verts_.x[poly_.next[i]] - a, q = centre - a;
    const double t = std::clamp(q.dot(e) / e.squaredNorm(), 0.0, 1.0);
    if ((q - t * e).squaredNorm() < reach * reach) return false;
  }
  return true;
}

void DpSystem::body_friction(VecArray<2>& out) {
  ff_->friction_forces(verts_, vertex_scratch_);
  out.assign(poly_.polygons(), Vec<2>::Zero());
  for (int i = 0; i < verts_.size(); ++i) out[poly_.owner[i]] += vertex_scratch_[i];
}

namespace {
/// In a thick funnel wall (FunnelCores::contains: its capsule or its slab), or beyond a side wall by at most T/2 plus
/// the vertex's own wall reach `side_reach`: in a wall, not through it. A side wall of walls with
/// a thickness is a half-space whose force keeps growing beyond its line (HopperWalls::add_side),
/// so a vertex pressed into it is pushed back from any depth; it is lost only when its whole
/// wall disk has passed the wall's core line (T/2 behind the surface). (Engine 0.5.0 stopped a
/// friction-only flow whose vertex was pressed 0.086 deep, 0.52 l0, as gone through.)
bool inside_a_wall(const FunnelCores& cores, const Hopper<2>& hopper, const Vec<2>& x, double side_reach) {
  const double h = cores.half_thickness();
  for (int k = 0; k < 2; ++k)
    if (cores.contains(k, x)) return true;
  for (int k = 2; k < 4; ++k) {
    if (!hopper.has_wall(k)) continue;
    const Vec<2> a = hopper.wall_start(k);
    const double beyond = k == 2 ? a[0] - x[0] : x[0] - a[0];
    if (x[1] > a[1] && beyond >= 0 && beyond <= h + side_reach) return true;
  }
  return false;
}
}  // namespace

void DpSystem::check_vertices(double t) const {
  // The contact search follows stretched edges (DpForceField::edge_bound); an edge this long
  // means the polygon is coming apart.
  if (ff_->longest_edge() > kMaxEdgeStretch * shape_.l0[1]) {
    std::ostringstream m;
    m << "a polygon edge stretched to " << ff_->longest_edge() << " (more than " << kMaxEdgeStretch
      << " l0 of the large species) at t = " << t;
    throw InstabilityError(m.str());
  }
  // A polygon may wrap around an orifice corner (walls are lines), with vertices under the
  // floor, or under a sloped funnel wall above the orifice plane (Hopper::beneath_funnel_wall;
  // engine 0.6.3: before, such a vertex of a polygon leaving a 20 deg funnel stopped the run as
  // "outside the container"); it has gone through a wall only if one of its edges cuts one.
  // Vertices beyond the side walls are outside the container.
  // thick walls (dp.wall_thickness): a vertex may be inside a wall; it is through only past the slab (FunnelCores::crossed)
  const FunnelCores& cores = ff_->funnel_cores();
  const bool thick = cores.half_thickness() > 0;
  for (int i = 0; i < verts_.size(); ++i) {
    const Vec<2>& x = verts_.x[i];
    const Vec<2>& next = verts_.x[poly_.next[i]];
    const int wall = thick ? cores.crossed(x, next) : hopper_.funnel_wall_crossed(x, next);
    const bool outside = !hopper_.contains(x) && !hopper_.beneath_funnel_wall(x) &&
                         !(thick && inside_a_wall(cores, hopper_, x, 0.5 * shape_.wall[verts_.species[i]]));
    if (outside || wall >= 0) {
      std::ostringstream msg;
      msg << "polygon " << poly_.owner[i] << " went through a wall at t = " << t << ": ";
      if (wall >= 0)
        msg << "its edge from vertex " << i << " (" << x.transpose() << ") to vertex " << poly_.next[i] << " ("
            << next.transpose() << ") cuts the " << (wall == 0 ? "left" : "right") << " funnel wall";
      else
        msg << "vertex " << i << " at (" << x.transpose() << ") is outside the container";
      throw InstabilityError(msg.str());
    }
  }
}

}  // namespace beverloo
