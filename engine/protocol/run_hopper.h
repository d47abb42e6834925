#pragma once
/// \file run_hopper.h
/// \brief The light face of the engine for those who run jobs (the worker, `simulate`, the
/// coordinator's settings): the run's options, its result and one function. It pulls in the
/// configuration and the result only, not the protocol, the models and the force terms behind
/// HopperRun (hopper_run.h), so a change there recompiles the engine, not the orchestrator.
#include <atomic>
#include <cstdint>
#include <string>

#include "../config.h"
#include "run_result.h"

namespace beverloo {

enum class ProgressMode { Auto, Terminal, Log, Quiet };

struct RunOptions {
  std::string output_dir;  ///< where checkpoint.h5, result.h5, summary.json go; empty: nowhere
  bool resume = false;     ///< continue from output_dir/checkpoint.h5 if it exists
  /// Without a checkpoint of its own: another job's checkpoint to continue, a job that differs
  /// from this one only in its stopping rules (SimConfig::trajectory_json) and stopped earlier
  /// (more flow time for a finished point). Used only where this job's own rules would not have
  /// stopped it before the checkpoint's step; otherwise the run starts from the beginning. The
  /// result is the one a run from the beginning gives, bit for bit.
  std::string continue_from;
  ProgressMode progress = ProgressMode::Quiet;
  /// Set asynchronously (signal handler): checkpoint at the end of the current step and stop.
  const std::atomic<bool>* stop_request = nullptr;
  /// If set, receives the current step now and then (a few times per simulated time unit), so that
  /// another thread can report progress (the worker's heartbeat file) without touching the run.
  std::atomic<std::int64_t>* progress_step = nullptr;
  /// Also checkpoint whenever this many wall seconds have passed since the last checkpoint (0:
  /// never). run.checkpoint_interval counts simulated time, which for stiff DP runs can be
  /// hours of wall time; a checkpoint at any step resumes bit-identically, so this changes no
  /// result, only how much work a SIGKILL or a lost node can cost.
  double checkpoint_wall_seconds = 600;
  /// Threads for the run's steps (SP: the force blocks and the integrator's loops; DP: the
  /// shape pass, the contact's list rows, the vertex sweeps). Every count gives the same result,
  /// bit for bit: the forces are summed in an order that the particle count alone fixes.
  int threads = 1;
  /// With threads > 1: use 1 thread instead while that runs the steps faster (a node whose
  /// other cores are busy; thread_governor.h). Off: always `threads` (bench, to time them).
  bool adapt_threads = true;
};

/// Runs one job of either dimension (dispatch on c.dimension): HopperRun<2> or <3>, prepare(), run().
RunResult run_hopper(const SimConfig& c, const RunOptions& options);

}  // namespace beverloo
