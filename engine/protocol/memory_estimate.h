#pragma once
/// \file memory_estimate.h
/// \brief A job's memory, estimated from its configuration before anything is allocated, and
/// the check that refuses a job this machine cannot hold (a ConfigError naming N, not an
/// allocation failure half-way through placement). The estimate is deliberately generous per
/// moving point (particle or DP vertex): state (x, v, f, species, mass, flags), the Verlet list
/// (reference positions, cells, rows, neighbours within sigma + skin), scratch of the terms and
/// observables. Measured peaks (maximum resident set, /usr/bin/time -v, 2026-12-02): 24 MB for
/// 50 000 2D SP particles, 26 MB for 50 000 3D, 23 MB for 2000 DP polygons, where the estimate
/// says 80, 94 and 76 MB: it refuses only what is far beyond the machine.
#include <cstdint>

#include "../config.h"

namespace beverloo {

/// Bytes the job will need at its peak, roughly (an upper estimate).
std::uint64_t estimated_memory_bytes(const SimConfig& c);

/// The memory this process may use: physical memory, or the cgroup limit if smaller.
std::uint64_t available_memory_bytes();

/// Throws ConfigError("N", ...) if the estimate exceeds the available memory.
void check_memory(const SimConfig& c);

}  // namespace beverloo
