#include "hopper.h"

#include <algorithm>

namespace beverloo {

Hopper<2>::Hopper(double W, double w, double theta_left_rad, double theta_right_rad) : w_(w) {
  auto make = [](Vec<2> a, Vec<2> b) {
    Segment s;
    s.a = a;
    s.length = (b - a).norm();
    s.u = (b - a) / s.length;
    return s;
  };
  const Segment absent{Vec<2>(kFar, kFar), Vec<2>(0, 1), -1};  // see has_wall()
  const Segment up_left{Vec<2>(-w / 2, 0), Vec<2>(0, 1), INFINITY}, up_right{Vec<2>(w / 2, 0), Vec<2>(0, 1), INFINITY};
  if (theta_left_rad == 0 || theta_right_rad == 0) {
    // one vertical wall: it is the container's side there; the other wall spans W - w
    const bool left_vertical = theta_left_rad == 0;
    const double theta = left_vertical ? theta_right_rad : theta_left_rad;
    double h = (W - w) * std::cos(theta) / std::sin(theta);
    if (std::fabs(h) < 1e-12 * W) h = 0;
    if (left_vertical) {
      h_left_ = 0, h_right_ = h, x_min_ = -w / 2, x_max_ = W - w / 2;
      seg_[0] = up_left;
      seg_[1] = make(Vec<2>(w / 2, 0), Vec<2>(x_max_, h));
      seg_[2] = absent;
      seg_[3] = Segment{Vec<2>(x_max_, h), Vec<2>(0, 1), INFINITY};
    } else {
      h_left_ = h, h_right_ = 0, x_min_ = w / 2 - W, x_max_ = w / 2;
      seg_[0] = make(Vec<2>(-w / 2, 0), Vec<2>(x_min_, h));
      seg_[1] = up_right;
      seg_[2] = Segment{Vec<2>(x_min_, h), Vec<2>(0, 1), INFINITY};
      seg_[3] = absent;
    }
    return;
  }
  const double run = (W - w) / 2;  // horizontal extent of each funnel wall
  h_left_ = run * std::cos(theta_left_rad) / std::sin(theta_left_rad);
  h_right_ = run * std::cos(theta_right_rad) / std::sin(theta_right_rad);
  if (std::fabs(h_left_) < 1e-12 * W) h_left_ = 0;  // cos(pi/2) is 6e-17, not 0
  if (std::fabs(h_right_) < 1e-12 * W) h_right_ = 0;
  x_min_ = -W / 2;
  x_max_ = W / 2;
  seg_[0] = make(Vec<2>(-w / 2, 0), Vec<2>(-W / 2, h_left_));
  seg_[1] = make(Vec<2>(w / 2, 0), Vec<2>(W / 2, h_right_));
  seg_[2] = Segment{Vec<2>(-W / 2, h_left_), Vec<2>(0, 1), INFINITY};
  seg_[3] = Segment{Vec<2>(W / 2, h_right_), Vec<2>(0, 1), INFINITY};
}

bool Hopper<2>::contains(const Vec<2>& p) const {
  const double x = p[0], y = p[1];
  // Below the orifice plane there are no walls: a particle there has exited (a crossing of the
  // plane outside the orifice is caught on exit), and it may fly out sideways beyond the
  // container while it falls (a soft polygon flung off an orifice corner does).
  if (y < 0) return true;
  if (x <= x_min_ || x >= x_max_) return false;
  // within the funnel the walls run from the orifice edges to the sides (a flat or vertical
  // wall has height 0: the side itself bounds x)
  const double left = y < h_left_ ? -w_ / 2 + (x_min_ + w_ / 2) * y / h_left_ : x_min_;
  const double right = y < h_right_ ? w_ / 2 + (x_max_ - w_ / 2) * y / h_right_ : x_max_;
  return x > left && x < right;
}

bool Hopper<2>::beneath_funnel_wall(const Vec<2>& p) const {
  if (p[1] < 0) return false;  // below the orifice plane: contains() takes it
  for (int k = 0; k < 2; ++k) {
    const Segment& s = seg_[k];
    if (s.length <= 0 || std::isinf(s.length)) continue;  // absent, or vertical (a ray)
    const double x_end = s.a[0] + s.length * s.u[0];      // where the wall meets its side wall
    const bool in_span = k == 0 ? (p[0] < s.a[0] && p[0] > x_end) : (p[0] > s.a[0] && p[0] < x_end);
    if (in_span && (p - s.a).dot(funnel_inward_normal(k)) < 0) return true;
  }
  return false;
}

int Hopper<2>::funnel_wall_crossed(const Vec<2>& p, const Vec<2>& q) const {
  if (std::min(p[1], q[1]) > funnel_top() || std::max(p[1], q[1]) < 0) return -1;  // the funnels lie in 0 <= y <= top
  for (int k = 0; k < 2; ++k) {
    // a vertical funnel wall is a ray: its piece up to the funnel's top (above it the
    // containment test, as for every side wall, catches a polygon outside)
    const double length = std::isinf(seg_[k].length) ? funnel_top() : seg_[k].length;
    if (length <= 0) continue;
    const Vec<2> a = seg_[k].a, b = seg_[k].a + length * seg_[k].u;
    if (segments_cross(a, b, p, q)) return k;
  }
  return -1;
}

}  // namespace beverloo
