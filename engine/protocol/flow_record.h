#pragma once
/// \file flow_record.h
/// \brief What the run accumulates and a checkpoint must hold: every exit, the clog clock and
/// the counters of the protocol.
#include <cstdint>
#include <vector>

namespace beverloo {

struct FlowRecord {
  std::vector<double> exit_time;         ///< t0 since gravity on
  std::vector<std::int64_t> exit_particle;
  std::vector<double> exit_size;         ///< reference area (2D) / volume (3D) of the exited particle
  double last_exit_time = 0;             ///< start of the clog clock (gravity on counts as an exit)
  std::int64_t reinjections = 0;
  std::int64_t reinjection_fallbacks = 0;  ///< placed above the pile instead of touching a particle
  double max_overlap_seen = 0;             ///< largest relative pair overlap in the flow phase
};

}  // namespace beverloo
