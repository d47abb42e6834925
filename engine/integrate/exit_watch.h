#pragma once
/// \file exit_watch.h
/// \brief What a fused drift looks for on behalf of the hopper's exit bookkeeping.
#include <array>

namespace beverloo {

/// Where a hopper's exit bookkeeping has work after a drift (ExitCounter::update): an item not
/// yet counted whose height is below the orifice plane (0), or a counted one below
/// exited_below[its species] (deep enough to be reinjected or taken out). A fused drift
/// (ForceField::drift_and_start_forces) tells whether any item is there, so that the
/// bookkeeping's own sweep over the items runs only when it has something to do.
struct ExitWatch {
  std::array<double, 2> exited_below{};
};

}  // namespace beverloo
