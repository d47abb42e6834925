#pragma once
/// \file flow_rate.h
/// \brief Steady-state flow rate from exit events (physics.md 7).
///
/// The exited reference areas are binned (width rate_bin) into a rate series r_k. The start-up
/// transient is removed with MSER-5 (White 1997: batch means of 5 bins, the truncation d that
/// minimises the variance of the remaining mean, searched over the first half), and never
/// shorter than min_transient. Q is the mean rate in the remaining window. Its standard error
/// comes from block averaging (Flyvbjerg & Petersen 1989): the bins are averaged in pairs
/// repeatedly; we take the largest standard error over the levels that still have at least
/// 16 blocks, which is conservative when the plateau is noisy.
#include <cmath>
#include <cstdint>
#include <vector>

#include "../config.h"
#include "flow_record.h"

namespace beverloo {

struct FlowRateEstimate {
  bool valid = false;      ///< false if the window is too short for an error estimate
  double Q = 0, Q_err = 0;
  double t_start = 0;      ///< start of the measurement window (end of the transient)
  double t_end = 0;
  std::int64_t exits_in_window = 0;
  int bins = 0;
  double rel_err() const { return Q > 0 ? Q_err / Q : INFINITY; }
};

class FlowRateEstimator {
 public:
  explicit FlowRateEstimator(const RunControls& rc) : rc_(rc) {}
  FlowRateEstimate estimate(const FlowRecord& rec, double t_now);
  /// Binned rate series of the last estimate (bin centres and rates), for the result file.
  const std::vector<double>& rates() const { return rate_; }

  /// MSER-5 truncation point (in bins) of a series; exposed for tests.
  static int mser5_truncation(const std::vector<double>& series);
  /// Block-averaging standard error of the mean of a series; exposed for tests.
  static double blocking_standard_error(const std::vector<double>& series, int min_blocks = 16);

 private:
  RunControls rc_;
  std::vector<double> rate_;
};

}  // namespace beverloo
