#include "hopper.h"

#include <algorithm>

namespace beverloo {

Hopper<2>::Hopper(double W, double w, double theta_left_rad, double theta_right_rad) : W_(W), w_(w) {
  const double run = (W - w) / 2;  // horizontal extent of each funnel wall
  // theta is measured from the direction of gravity: 90 deg is a flat bottom (height 0).
  h_left_ = run * std::cos(theta_left_rad) / std::sin(theta_left_rad);
  h_right_ = run * std::cos(theta_right_rad) / std::sin(theta_right_rad);
  if (std::fabs(h_left_) < 1e-12 * W) h_left_ = 0;  // cos(pi/2) is 6e-17, not 0
  if (std::fabs(h_right_) < 1e-12 * W) h_right_ = 0;
  auto make = [](Vec<2> a, Vec<2> b) {
    Segment s;
    s.a = a;
    s.length = (b - a).norm();
    s.u = (b - a) / s.length;
    return s;
  };
  seg_[0] = make(Vec<2>(-w / 2, 0), Vec<2>(-W / 2, h_left_));
  seg_[1] = make(Vec<2>(w / 2, 0), Vec<2>(W / 2, h_right_));
  seg_[2] = Segment{Vec<2>(-W / 2, h_left_), Vec<2>(0, 1), INFINITY};
  seg_[3] = Segment{Vec<2>(W / 2, h_right_), Vec<2>(0, 1), INFINITY};
}

bool Hopper<2>::contains(const Vec<2>& p) const {
  const double x = p[0], y = p[1];
  // Below the orifice plane there are no walls: a particle there has exited (a crossing of the
  // plane outside the orifice is caught on exit), and it may fly out sideways beyond +-W/2
  // while it falls (a soft polygon flung off an orifice corner does).
  if (y < 0) return true;
  if (std::fabs(x) >= W_ / 2) return false;
  const double left = y < h_left_ ? -w_ / 2 - (W_ - w_) / 2 * y / h_left_ : -W_ / 2;
  const double right = y < h_right_ ? w_ / 2 + (W_ - w_) / 2 * y / h_right_ : W_ / 2;
  return x > left && x < right;
}

int Hopper<2>::funnel_wall_crossed(const Vec<2>& p, const Vec<2>& q) const {
  if (std::min(p[1], q[1]) > funnel_top() || std::max(p[1], q[1]) < 0) return -1;  // the funnels lie in 0 <= y <= top
  auto side = [](const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) {
    const Vec<2> ab = b - a, ac = c - a;
    return ab[0] * ac[1] - ab[1] * ac[0];
  };
  for (int k = 0; k < 2; ++k) {
    const Vec<2> a = seg_[k].a, b = seg_[k].a + seg_[k].length * seg_[k].u;
    if (side(a, b, p) * side(a, b, q) < 0 && side(p, q, a) * side(p, q, b) < 0) return k;
  }
  return -1;
}

}  // namespace beverloo
