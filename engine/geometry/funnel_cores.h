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
/// A vertex through the core has gone through the wall (an edge crossing a core is a leak).
/// The side walls of such a container are half-spaces (HopperWalls::add_side): a vertex beyond
/// one by more than T/2, the funnel cores' depth, has gone through it.
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
      len_[k] = hopper.wall_length(k) - half_;  // ends under the wall's far end (a ray stays a ray)
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
  /// Every core point lies within this distance of its wall's segment (the lip's centre is
  /// the farthest): the walls' list reach grows by it and by T/2.
  double offset_from_wall() const { return half_ * std::sqrt(2.0); }
  /// The core (0 or 1) that the segment p -> q properly crosses, or -1.
  int crossed(const Vec<2>& p, const Vec<2>& q) const {
    for (int k = 0; k < 2; ++k) {
      if (len_[k] <= 0) continue;
      // a ray (vertical funnel wall): its piece up to the higher of p and q
      const double length = std::isinf(len_[k]) ? std::max(0.0, std::max(p[1], q[1]) - a_[k][1]) : len_[k];
      if (segments_cross(a_[k], a_[k] + length * u_[k], p, q)) return k;
    }
    return -1;
  }

 private:
  double half_;
  Vec<2> a_[2], u_[2];
  double len_[2];
};

}  // namespace beverloo
