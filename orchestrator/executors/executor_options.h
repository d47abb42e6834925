#pragma once
/// \file executor_options.h
/// \brief Command-line options an executor declares for itself. The CLI adds every executor's
/// options to `run` and `campaign run` from these rows and hands the given values back as text;
/// the executor parses its own (SlurmExecutor::settings_from). So a new executor's options live
/// in its own files, and the CLI and the coordinator know none of them.
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace beverloo {

struct ExecutorOption {
  enum class Kind {
    Text,      ///< one string
    Integer,   ///< one integer in [lo, hi]
    Real,      ///< one number in (lo, hi] when lo_open, else [lo, hi]
    TextList,  ///< repeatable: every occurrence kept, in order
  };
  std::string flag;  ///< "--partition"
  std::string help;  ///< one line, with the default
  Kind kind = Kind::Text;
  double lo = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no bound
  double hi = std::numeric_limits<double>::quiet_NaN();
  bool lo_open = false;
};

/// The values given on the command line, by flag: one string each (a TextList: every occurrence).
/// Checked against the declaring row's kind and range by the CLI.
using ExecutorOptionValues = std::map<std::string, std::vector<std::string>>;

/// The number a value of an Integer or Real option stands for; throws ConfigError naming the
/// flag when it is not a finite number, not an integer (Integer), or outside the row's range.
double option_number(const ExecutorOption& option, const std::string& text);

}  // namespace beverloo
