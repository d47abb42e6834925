#include "polygons.h"

#include <cmath>

#include "../units.h"

namespace beverloo {

DpShape DpShape::from_config(const SimConfig& c) {
  DpShape s;
  s.n_v = c.dp.n_v;
  s.smooth = c.model == "dp_smooth";
  const Species sp = Species::bidisperse(2, c.size_ratio);
  const double nv = s.n_v, t = std::tan(units::pi / nv);
  for (int k = 0; k < 2; ++k) {
    s.a0[k] = sp.ref_size[k];
    s.l0[k] = std::sqrt(4 * s.a0[k] * nv * t) / nv;  // physics.md 4
    s.delta[k] = s.smooth ? c.dp.contact_width * s.l0[k] : s.l0[k];
    s.wall[k] = c.dp.wall_width ? *c.dp.wall_width * s.l0[k] : s.delta[k];
    s.vertex_mass[k] = sp.mass[k] / nv;
    s.circumradius[k] = s.l0[k] / (2 * std::sin(units::pi / nv));
  }
  s.wall_thickness = c.dp.wall_thickness * s.l0[0];
  return s;
}

PolygonSet PolygonSet::uniform(int n, int n_v) {
  PolygonSet p;
  p.first.resize(n + 1);
  p.owner.resize(std::size_t(n) * n_v);
  p.next.resize(p.owner.size());
  p.prev.resize(p.owner.size());
  for (int m = 0; m <= n; ++m) p.first[m] = m * n_v;
  for (int m = 0; m < n; ++m)
    for (int k = 0; k < n_v; ++k) {
      const int i = m * n_v + k;
      p.owner[i] = m;
      p.next[i] = m * n_v + (k + 1) % n_v;
      p.prev[i] = m * n_v + (k + n_v - 1) % n_v;
    }
  return p;
}

double polygon_area(const PolygonSet& p, const VecArray<2>& x, int m) {
  double a = 0;
  for (int i = p.first[m]; i < p.first[m + 1]; ++i) {
    const Vec<2>& r = x[i];
    const Vec<2>& q = x[p.next[i]];
    a += r[0] * q[1] - q[0] * r[1];
  }
  return 0.5 * a;
}

Vec<2> polygon_centroid(const PolygonSet& p, const VecArray<2>& x, int m) {
  Vec<2> c = Vec<2>::Zero();
  for (int i = p.first[m]; i < p.first[m + 1]; ++i) c += x[i];
  return c / double(p.first[m + 1] - p.first[m]);
}

double polygon_perimeter(const PolygonSet& p, const VecArray<2>& x, int m) {
  double l = 0;
  for (int i = p.first[m]; i < p.first[m + 1]; ++i) l += (x[p.next[i]] - x[i]).norm();
  return l;
}

namespace {
double cross(const Vec<2>& a, const Vec<2>& b) { return a[0] * b[1] - a[1] * b[0]; }
bool segments_intersect(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c, const Vec<2>& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}
}  // namespace

bool polygon_is_simple(const PolygonSet& p, const VecArray<2>& x, int m) {
  for (int i = p.first[m]; i < p.first[m + 1]; ++i)
    for (int j = i + 1; j < p.first[m + 1]; ++j) {
      if (p.next[i] == j || p.next[j] == i) continue;  // adjacent edges share a vertex
      if (segments_intersect(x[i], x[p.next[i]], x[j], x[p.next[j]])) return false;
    }
  return true;
}

void place_regular_polygon(const PolygonSet& p, const DpShape& shape, ParticleState<2>& verts, int m,
                           const Vec<2>& centre, double angle, const Vec<2>& velocity) {
  const int species = verts.species[p.first[m]];
  const double R = shape.circumradius[species];
  const int n = p.first[m + 1] - p.first[m];
  for (int k = 0; k < n; ++k) {
    const int i = p.first[m] + k;
    const double phi = angle + 2 * units::pi * k / n;
    verts.x[i] = centre + R * Vec<2>(std::cos(phi), std::sin(phi));
    verts.v[i] = velocity;
  }
}

}  // namespace beverloo
