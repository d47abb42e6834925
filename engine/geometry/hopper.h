#pragma once
/// \file hopper.h
/// \brief Hopper containers. Every wall is a finite object queried by its nearest point, so the
/// orifice edges are corners (a particle there feels the wall's end point, physics.md 2).
///
/// 2D (Hopper<2>): gravity along -y, orifice from (-w/2, 0) to (w/2, 0) (the orifice is the
/// origin of the protocol: exits, the centre line, the corners). theta is measured from the
/// direction of gravity (90: flat floor; 0: a vertical wall). Each funnel wall spans a
/// horizontal run: (W - w)/2 each when neither wall is vertical (the container then lies
/// symmetric about the orifice, from -W/2 to W/2); a vertical wall rises straight from its
/// orifice edge and the other wall spans all of W - w, so the orifice sits in the container's
/// corner (the experiments' 45/0 hopper). At most one wall may be vertical. Walls:
///   0 left funnel  segment (-w/2, 0) -> (x_min, h_left),  h_left  = run_left cot(theta_left)
///   1 right funnel segment ( w/2, 0) -> (x_max, h_right), h_right = run_right cot(theta_right)
///   2 left side    ray from (x_min, h_left) upward
///   3 right side   ray from (x_max, h_right) upward
/// A vertical funnel wall is a ray from its orifice edge upward, and it is its side wall: the
/// side wall's slot then holds no wall (its nearest point lies kFar away, so that the loops
/// over walls need no special case).
/// 3D (Hopper<3>): gravity along -z, cylinder of diameter W from z = 0 upward, flat base in the
/// plane z = 0 with a circular orifice of diameter w on the axis. Walls: 0 base annulus,
/// 1 cylinder mantle. Its bottom rim and the orifice rim are the corners.
#include <cmath>

#include "../vec.h"

namespace beverloo {

template <int D>
class Hopper;

/// True if segments a-b and p-q properly cross (each one's ends strictly on both sides of the
/// other's line): a polygon edge cutting a wall.
inline bool segments_cross(const Vec<2>& a, const Vec<2>& b, const Vec<2>& p, const Vec<2>& q) {
  auto side = [](const Vec<2>& u, const Vec<2>& v, const Vec<2>& c) {
    const Vec<2> uv = v - u, uc = c - u;
    return uv[0] * uc[1] - uv[1] * uc[0];
  };
  return side(a, b, p) * side(a, b, q) < 0 && side(p, q, a) * side(p, q, b) < 0;
}

template <>
class Hopper<2> {
 public:
  static constexpr int kNumWalls = 4;
  /// The funnel walls carry the pile (the side walls only confine it).
  static constexpr bool is_floor(int k) { return k < 2; }
  Hopper(double W, double w, double theta_left_rad, double theta_right_rad);

  /// Nearest point of wall k to p.
  Vec<2> nearest_point(int k, const Vec<2>& p) const {
    const Segment& s = seg_[k];
    double t = (p - s.a).dot(s.u);
    t = t < 0 ? 0 : (t > s.length ? s.length : t);
    return s.a + t * s.u;
  }
  /// True if p lies inside the container (between the walls) or below the orifice plane.
  bool contains(const Vec<2>& p) const;
  /// True if p lies under a sloped funnel wall: above the orifice plane, beyond the wall's line
  /// and within its horizontal span (between its orifice edge and the side wall). Outside the
  /// container, but reached from below the orifice plane without crossing a wall: a polygon
  /// leaving the orifice may wrap around its edge, and under a funnel steeper than flat its
  /// vertices rise above y = 0 there (a flat floor's underside is y < 0, which contains()
  /// takes). A vertical wall has no underside (it spans no x).
  bool beneath_funnel_wall(const Vec<2>& p) const;
  /// The funnel wall (0 or 1) that the segment p -> q properly crosses, or -1: a polygon edge
  /// crossing a wall has been pierced by it (walls are lines without thickness, so a polygon
  /// may wrap around an orifice corner, but none of its edges may cut a wall).
  int funnel_wall_crossed(const Vec<2>& p, const Vec<2>& q) const;
  /// The container's lateral extent above the funnel: x_min .. x_max (W wide), its centre
  /// (0 unless a wall is vertical) and half its width.
  double x_min() const { return x_min_; }
  double x_max() const { return x_max_; }
  double lateral_centre() const { return 0.5 * (x_min_ + x_max_); }
  double half_width() const { return 0.5 * (x_max_ - x_min_); }
  double funnel_top() const { return std::max(h_left_, h_right_); }
  /// True only if wall k is surely farther than `reach` from p: the distance to the wall's line
  /// (a lower bound of the distance to the wall) beyond reach by more than a rounding margin.
  /// A cheap test before nearest_point() for the many particles far from every wall; it never
  /// decides a case that the exact test would decide otherwise.
  bool beyond(int k, const Vec<2>& p, double reach) const {
    const Segment& s = seg_[k];
    const double ux = p[0] - s.a[0], uy = p[1] - s.a[1];
    const double line_distance = std::fabs(ux * s.u[1] - uy * s.u[0]);
    return line_distance > reach + kRounding * (1 + std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(s.a[0]) + std::fabs(s.a[1]));
  }
  /// False for the side wall of a vertical funnel wall (which is that side wall itself).
  bool has_wall(int k) const { return seg_[k].length >= 0; }
  /// Where an absent wall's "nearest point" lies: far beyond any interaction, finite (its
  /// squared distance, ~1e300, stays below the largest double).
  static constexpr double kFar = 1e150;
  /// beyond()'s margin per unit of coordinate size (rounding is ~1e-16 of it)
  static constexpr double kRounding = 1e-12;
  double orifice_half_width() const { return w_ / 2; }
  /// Lateral distance of p from the orifice axis (|x|).
  static double lateral(const Vec<2>& p) { return std::fabs(p[0]); }
  /// Wall k as a segment: start (a funnel wall's start is its orifice edge), unit direction,
  /// length (INFINITY for a ray, negative for an absent wall).
  Vec<2> wall_start(int k) const { return seg_[k].a; }
  Vec<2> wall_direction(int k) const { return seg_[k].u; }
  double wall_length(int k) const { return seg_[k].length; }
  /// Unit normal of funnel wall k (0 or 1) toward the inside of the container.
  Vec<2> funnel_inward_normal(int k) const {
    const Vec<2> u = seg_[k].u;
    return k == 0 ? Vec<2>(u[1], -u[0]) : Vec<2>(-u[1], u[0]);
  }

 private:
  struct Segment {
    Vec<2> a, u;
    double length;
  };
  double w_, h_left_, h_right_, x_min_, x_max_;
  Segment seg_[kNumWalls];
};

template <>
class Hopper<3> {
 public:
  static constexpr int kNumWalls = 2;
  static constexpr bool is_floor(int k) { return k == 0; }  ///< the base carries the pile
  Hopper(double W, double w) : R_(W / 2), r_orifice_(w / 2) {}

  Vec<3> nearest_point(int k, const Vec<3>& p) const {
    const double rho = std::hypot(p[0], p[1]);
    // Radial unit vector; on the axis any direction is nearest, pick +x deterministically.
    const double ex = rho > 0 ? p[0] / rho : 1.0, ey = rho > 0 ? p[1] / rho : 0.0;
    if (k == 0) {  // base annulus r_orifice <= rho <= R in the plane z = 0
      const double rc = rho < r_orifice_ ? r_orifice_ : (rho > R_ ? R_ : rho);
      return Vec<3>(rc * ex, rc * ey, 0.0);
    }
    return Vec<3>(R_ * ex, R_ * ey, p[2] > 0 ? p[2] : 0.0);  // mantle, z >= 0
  }
  /// As Hopper<2>::beyond(): the base's plane, the mantle's cylinder.
  bool beyond(int k, const Vec<3>& p, double reach) const {
    const double margin = 1e-12 * (1 + std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) + R_);
    if (k == 0) return std::fabs(p[2]) > reach + margin;
    const double inner = R_ - reach - margin;  // inside this radius the mantle is beyond reach
    return inner > 0 && p[0] * p[0] + p[1] * p[1] < inner * inner * (1 - 1e-12);
  }
  /// True inside the cylinder or below the base plane (no walls there; see the 2D hopper).
  bool contains(const Vec<3>& p) const { return p[2] < 0 || std::hypot(p[0], p[1]) < R_; }
  double half_width() const { return R_; }
  double lateral_centre() const { return 0.0; }  ///< the axis
  double funnel_top() const { return 0.0; }
  double orifice_half_width() const { return r_orifice_; }
  static double lateral(const Vec<3>& p) { return std::hypot(p[0], p[1]); }

 private:
  double R_, r_orifice_;
};

}  // namespace beverloo
