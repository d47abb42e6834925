#include "executor_options.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/errors.h"

namespace beverloo {
namespace {
std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

double option_number(const ExecutorOption& o, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw ConfigError(o.flag, "must be a finite number, got \"" + text + "\"");
  if (o.kind == ExecutorOption::Kind::Integer && v != std::floor(v))
    throw ConfigError(o.flag, "must be an integer, got \"" + text + "\"");
  const bool below = o.lo == o.lo && (o.lo_open ? v <= o.lo : v < o.lo);
  const bool above = o.hi == o.hi && v > o.hi;
  if (below || above) {
    std::string range = o.lo == o.lo ? std::string(o.lo_open ? "> " : ">= ") + shortest(o.lo) : "";
    if (o.hi == o.hi) range += (range.empty() ? "<= " : " and <= ") + shortest(o.hi);
    throw ConfigError(o.flag, "must be " + range + ", got " + text);
  }
  return v;
}

}  // namespace beverloo
