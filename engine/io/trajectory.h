#pragma once
/// \file trajectory.h
/// \brief Trajectory frames in H5MD 1.1 (de Buyl et al. 2014), readable by OVITO and MDAnalysis:
///   /h5md                          version = [1, 1]; author/, creator/
///   /particles/all/box             dimension, boundary = ["none", ...]; edges (container extent)
///   /particles/all/position/{step, time, value[frame][N][D]}
///   /particles/all/species         [N] int32, 0 = small, 1 = large (time-independent)
///   /parameters                    W, w, theta_w_left_deg, theta_w_right_deg (the walls)
/// The file is flushed after each frame. On resume, frames after the checkpoint are dropped
/// so that a resumed run writes the same frames as one that never stopped.
#include <cstdint>
#include <string>

#include "../config.h"
#include "../state.h"
#include "h5.h"

namespace beverloo {

template <int D>
class H5mdTrajectory {
 public:
  /// Creates path, or (resume) reopens it keeping frames with step <= keep_until_step.
  H5mdTrajectory(const std::string& path, const SimConfig& c, const ParticleState<D>& s, double box_height,
                 std::int64_t keep_until_step = -1);
  void write_frame(const ParticleState<D>& s, double time);
  std::int64_t frames() const { return frames_; }

 private:
  void create(const std::string& path, const SimConfig& c, const ParticleState<D>& s, double box_height);
  H5Handle file_;
  std::int64_t frames_ = 0;
  std::vector<double> buffer_;
};

}  // namespace beverloo
