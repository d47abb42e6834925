#pragma once
/// \file thread_governor.h
/// \brief How many threads a job with --threads T > 1 uses right now: T or 1, whichever ran
/// its steps faster lately. On a node whose other cores are busy (a shared cluster node, or a
/// second job on this machine), a team of T threads waits at every step's barriers for the
/// thread that shares a core: measured here, T = 2 took 2.5x as long as T = 1 with the other
/// core loaded, and no OpenMP wait policy helped in both states (docs/performance.md). Since
/// a job's results are the same bits for every thread count, the count may change between any
/// two steps: the governor measures windows of steps and keeps the faster count, probing the
/// other one window in every kProbeEvery, so a job follows its node's load.
#include <algorithm>
#include <chrono>

namespace beverloo {

class ThreadGovernor {
 public:
  static constexpr int kWindowSteps = 1000;  ///< steps per measured window
  static constexpr int kProbeEvery = 8;      ///< windows between probes after a change
  static constexpr int kProbeEveryMost = 128;  ///< ... doubling while the choice holds

  explicit ThreadGovernor(int requested) : requested_(requested), current_(requested) {}
  bool active() const { return requested_ > 1; }
  int threads() const { return current_; }

  /// The end of a window on threads() that took `seconds`: returns the count for the next one.
  int end_window(double seconds) {
    const int slot = current_ == 1 ? 0 : 1;
    time_[slot] = seconds;
    if (probing_) {  // the probe is done: keep the faster of the two latest windows
      probing_ = false;
      const int best = time_[0] < time_[1] ? 1 : requested_;
      // a probe that confirms the choice spaces the next one out (a probe of the slower count
      // costs a slow window); a change brings them back close, to follow a changing load
      interval_ = best == best_ ? std::min(2 * interval_, kProbeEveryMost) : kProbeEvery;
      best_ = best;
      current_ = best_;
      since_probe_ = 0;
      return current_;
    }
    if (++since_probe_ >= interval_ || time_[1 - slot] < 0) {  // probe the other count
      probing_ = true;
      current_ = current_ == 1 ? requested_ : 1;
    }
    return current_;
  }
  /// Called after every step; true when the thread count changes before the next step.
  bool after_step() {
    if (!active()) return false;
    if (steps_ == 0) start_ = std::chrono::steady_clock::now();
    if (++steps_ < kWindowSteps) return false;
    const auto now = std::chrono::steady_clock::now();
    const int before = current_;
    end_window(std::chrono::duration<double>(now - start_).count());
    steps_ = 0;
    return current_ != before;
  }

 private:
  int requested_, current_, best_ = 0;
  double time_[2] = {-1, -1};  ///< the latest window's seconds on 1 thread, on requested_
  int since_probe_ = 0, interval_ = kProbeEvery;
  bool probing_ = false;
  int steps_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace beverloo
