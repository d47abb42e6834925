#pragma once
/// \file make_hopper.h
/// \brief The hopper of a job: degrees at the JSON boundary, radians inside.
#include "../config.h"
#include "../units.h"
#include "hopper.h"

namespace beverloo {

template <int D>
Hopper<D> make_hopper(const SimConfig& c) {
  if constexpr (D == 2)
    return Hopper<2>(c.W, c.w, units::deg_to_rad(c.theta_w_left_deg), units::deg_to_rad(c.theta_w_right_deg));
  else
    return Hopper<3>(c.W, c.w);
}

}  // namespace beverloo
