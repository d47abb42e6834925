#pragma once
/// \file exit_counter.h
/// \brief Counts a particle as exited once, when its centre crosses the orifice plane, and
/// reports which exited particles have fallen far enough to be reinjected.
#include <stdexcept>
#include <string>
#include <vector>

#include "../geometry/hopper.h"
#include "../integrate/exit_watch.h"
#include "core/errors.h"
#include "../state.h"
#include "flow_record.h"

namespace beverloo {

template <int D>
class ExitCounter {
 public:
  ExitCounter(const Hopper<D>& hopper, double drop_depth_diameters, int n)
      : hopper_(hopper), drop_depth_(drop_depth_diameters) {
    to_reinject_.reserve(n);
  }
  /// Call after the drift of each step at time t. Fills to_reinject().
  void update(ParticleState<D>& s, double t, FlowRecord& rec) {
    to_reinject_.clear();
    const int n = s.size();
    const double half_w = hopper_.orifice_half_width();
    const ExitWatch w = watch(s.sp);
    for (int i = 0; i < n; ++i) {
      const double h = s.x[i][kUp<D>];
      if (!s.exited[i]) {
        if (h >= 0) continue;
        if (Hopper<D>::lateral(s.x[i]) > half_w + slack_)
          throw InstabilityError("particle " + std::to_string(s.id[i]) + " crossed the orifice plane through the wall at t = " +
                                 std::to_string(t));
        rec.exit_time.push_back(t);
        rec.exit_particle.push_back(s.id[i]);
        rec.exit_size.push_back(s.sp.ref_size[s.species[i]]);
        rec.last_exit_time = t;
        s.exited[i] = 1;
      } else if (h < w.exited_below[s.species[i]]) {
        to_reinject_.push_back(i);
      }
    }
  }
  /// Instead of update() when a drift saw no particle where watch() says update() has work.
  void none_to_count() { to_reinject_.clear(); }
  /// Where update() has work: a particle not yet counted below the orifice plane, or a counted
  /// one deeper than the drop depth (in its own diameters).
  ExitWatch watch(const Species& sp) const {
    return {{-drop_depth_ * sp.sigma[0], -drop_depth_ * sp.sigma[1]}};
  }
  const std::vector<int>& to_reinject() const { return to_reinject_; }
  /// How far beyond the orifice edge a centre may cross the orifice plane and still count as an
  /// exit. 0 for disks. A deformable polygon draped around an orifice corner can have its
  /// centroid there (its vertices are checked against the walls one by one).
  void set_lateral_slack(double slack) { slack_ = slack; }

 private:
  const Hopper<D>& hopper_;
  double drop_depth_;
  double slack_ = 0;
  std::vector<int> to_reinject_;
};

}  // namespace beverloo
