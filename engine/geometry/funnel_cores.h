#pragma once
/// \file funnel_cores.h
/// \brief Funnel walls of a thickness T (DP: dp.wall_thickness), as the authors' code has its
/// floor: each funnel wall a slab T thick behind its line, its end at the orifice rounded (a
/// bead of diameter T, hopper2D.cpp 1682-1687: sb = l0, centred sb/2 behind the exit plane
/// and sb/2 beside the orifice edge).
///
/// A slab with a rounded end is a capsule: every point within T/2 of a core segment, the wall's
/// segment moved T/2 behind its line and starting T/2 along it from the orifice edge. So the
/// wall's surface stays where the line was (the container is unchanged), the lip's innermost
/// point lies T/2 behind the orifice edge (for a flat floor: the clear width is w, at depth T/2),
/// and a vertex's distance to the wall, |r - core| - T/2, is continuous everywhere, negative
/// inside the wall: the wall keeps pushing a vertex that has entered it back out, up to an
/// energy (E_w/2)(1 + T/sigma_w)^2 at the core, where a line wall (T = 0) gives way at E_w/2.
/// Below the core line (the slab's lower half), as in the authors' code, where the bottom
/// wall's force grows with a vertex's depth down to the exit plane T below the surface
/// (hopper2D.cpp ~1745-1760) and nothing acts beyond, the slab pushes back into the container:
/// d = -T/2 - |s| with s the depth below the core line; under the slab's bottom the capsule's
/// distance holds again (the floor's underside, engine 0.6.2). Within T of the lip (along the wall) it turns over smoothly to
/// the lip's push outward, d = -T/2 + |s| (1 - 2 t / T) at a distance t along the core, so that
/// the distance (and the energy) stays continuous everywhere (engine 0.6.0; 0.5.0 took the
/// capsule everywhere and pushed a vertex past the core out through the floor: friction-only
/// flows lost vertices there after impacts, docs/validation.md). A polygon has gone through a
/// funnel wall when an edge crosses the slab's bottom (T behind the surface) or, within T/2 of
/// the lip, where the slab pushes outward, the core. The side walls of such a container are
/// half-spaces (HopperWalls::add_side).
#include <cmath>

#include "hopper.h"

namespace beverloo {

class FunnelCores {
 public:
  FunnelCores(const Hopper<2>& hopper, double thickness) : half_(0.5 * thickness) {
    for (int k = 0; k < 2; ++k) {
      const Vec<2> u = hopper.wall_direction(k), n = hopper.funnel_inward_normal(k);
      a_[k] = hopper.wall_start(k) + half_ * u - half_ * n;
      u_[k] = u;
      n_[k] = n;
      len_[k] = hopper.wall_length(k) - half_;  // ends under the wall's far end (a ray stays a ray)
    }
    for (int k = 2; k < 4; ++k) {
      side_[k - 2] = hopper.has_wall(k);
      side_start_[k - 2] = hopper.wall_start(k);
    }
  }
  double half_thickness() const { return half_; }
  /// The lip's centre at orifice edge k (the core's start).
  Vec<2> lip_centre(int k) const { return a_[k]; }
  Vec<2> nearest_point(int k, const Vec<2>& p) const {
    double t = (p - a_[k]).dot(u_[k]);
    t = t < 0 ? 0 : (t > len_[k] ? len_[k] : t);
    return a_[k] + t * u_[k];
  }
  /// Whether p lies in the slab's lower half: below core k's line, above the slab's bottom (T
  /// behind the surface, the authors' exit plane), within the core's span (the distance is the
  /// slab's, below); elsewhere it is the capsule's |p - nearest_point| - T/2, which under the
  /// slab's bottom is its underside: a vertex there (one that swung round the lip from the
  /// orifice) is pushed down, away from the floor, within its own reach, and nothing acts
  /// further down. (Engine 0.6.0 and 0.6.1 took the slab's push up to any depth, as far as the
  /// list's wall masks happened to reach: an exited vertex falling just beside the lip was
  /// pulled up hard or not at all, depending on when the list was built.)
  bool in_slab_region(int k, const Vec<2>& p) const {
    const Vec<2> q = p - a_[k];
    const double t = q.dot(u_[k]), s = q.dot(n_[k]);
    return s < 0 && s >= -half_ && t > 0 && t < len_[k];
  }
  /// In the slab's region: the distance d of p from funnel wall k's surface (negative: inside),
  /// -T/2 - s g(t) with s < 0 the signed distance from the core line and g = 1 - 2t/T within T
  /// of the lip, else -1; and its gradient.
  double slab_distance(int k, const Vec<2>& p, Vec<2>& gradient) const {
    const Vec<2> q = p - a_[k];
    const double t = q.dot(u_[k]), s = q.dot(n_[k]);
    const double span = 2 * half_;  // the turn-over length T
    const double g = t < span ? 1 - 2 * t / span : -1.0;
    gradient = (t < span ? 2 * s / span : 0.0) * u_[k] - g * n_[k];
    return -half_ - s * g;
  }
  /// Whether p is in funnel wall k: within T/2 of its core, or in its slab down to the bottom.
  bool contains(int k, const Vec<2>& p) const {
    if ((p - nearest_point(k, p)).squaredNorm() <= half_ * half_) return true;
    return in_slab_region(k, p);  // the slab's lower half ends at its bottom
  }
  /// The walls (bits 1 << k, Hopper<2>'s numbering) whose force may act on a point within
  /// `reach` of x beyond their reach from the wall's line: a side wall where x is within
  /// `reach` of the half-space beyond it (above its start; HopperWalls::add_side pushes back
  /// from any distance). The funnel walls act within T + a vertex's reach of their line, which
  /// the masks' reach covers (DpForceField). The walls' list masks take these bits (NeighborList::
  /// set_walls_acting_beyond), so that a vertex's wall force depends on where it is, not on
  /// where it was when the list was built.
  std::uint8_t walls_acting_beyond(const Vec<2>& x, double reach) const {
    std::uint8_t mask = 0;
    for (int k = 2; k < 4; ++k) {
      if (!side_[k - 2]) continue;
      const Vec<2>& a = side_start_[k - 2];
      const double inward = k == 2 ? 1.0 : -1.0;  // the left side wall's inside is +x
      if (x[1] > a[1] - reach && (x[0] - a[0]) * inward < reach) mask |= std::uint8_t(1u << k);
    }
    return mask;
  }
  /// Every core point lies within this distance of its wall's segment (the lip's centre is
  /// the farthest): the walls' list reach grows by it and by T/2.
  double offset_from_wall() const { return half_ * std::sqrt(2.0); }
  /// The funnel wall (0 or 1) that the segment p -> q goes through, or -1: it properly crosses
  /// the slab's bottom, or the core within T/2 of the lip (where the slab pushes outward).
  int crossed(const Vec<2>& p, const Vec<2>& q) const {
    for (int k = 0; k < 2; ++k) {
      if (len_[k] <= 0) continue;
      // a ray (vertical funnel wall): its piece up to the higher of p and q
      const double length = std::isinf(len_[k]) ? std::max(0.0, std::max(p[1], q[1]) - a_[k][1]) : len_[k];
      const Vec<2> bottom = a_[k] - half_ * n_[k];
      if (segments_cross(bottom, bottom + length * u_[k], p, q)) return k;
      if (segments_cross(a_[k], a_[k] + std::min(half_, length) * u_[k], p, q)) return k;
    }
    return -1;
  }

 private:
  double half_;
  Vec<2> a_[2], u_[2], n_[2];
  double len_[2];
  bool side_[2];  ///< side walls 2 and 3 present (no side wall beside a vertical funnel wall)
  Vec<2> side_start_[2];
};

}  // namespace beverloo
