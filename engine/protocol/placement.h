#pragma once
/// \file placement.h
/// \brief Step 1 of the protocol: N bidisperse particles (N/2 small, the rest large) placed
/// uniformly at random above the funnel, zero velocity; overlaps are removed afterwards by FIRE.
#include "../config.h"
#include "../geometry/hopper.h"
#include "../rng.h"
#include "../state.h"

namespace beverloo {

template <int D>
void place_randomly(ParticleState<D>& s, const SimConfig& c, const Hopper<D>& hopper, Rng& rng);

}  // namespace beverloo
