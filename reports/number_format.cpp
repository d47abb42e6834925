#include "number_format.h"

#include <cmath>
#include <cstdio>

namespace beverloo {

std::string format_value(double value, int digits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char b[48];
  std::snprintf(b, sizeof b, "%.*g", digits, value);
  return b;
}

std::string format_with_error(double value, double error, const std::string& pm) {
  if (!std::isfinite(value) || !std::isfinite(error) || error <= 0) return format_value(value);
  const int exponent = static_cast<int>(std::floor(std::log10(error)));
  const double leading = error / std::pow(10.0, exponent);  // in [1, 10)
  // two digits for 1.0-2.9 (rounding 0.14 to 0.1 would lose 30 %), else one
  // (with a tolerance: 0.3 / 0.1 is 2.9999999999999996 in binary)
  int place = leading < 3 - 1e-9 ? exponent - 1 : exponent;  // the decimal place of the last digit kept
  // rounding may carry into a new digit (0.096 -> 0.10): keep the digit count the rule asks for
  const double rounded_error = std::round(error / std::pow(10.0, place)) * std::pow(10.0, place);
  if (rounded_error >= (3 - 1e-9) * std::pow(10.0, place + 1) && leading < 3 - 1e-9) ++place;
  const int decimals = place < 0 ? -place : 0;
  const double scale = std::pow(10.0, place);
  const double v = std::round(value / scale) * scale, e = std::round(error / scale) * scale;
  char vb[48], eb[48];
  std::snprintf(vb, sizeof vb, "%.*f", decimals, v == 0 ? 0.0 : v);  // no "-0.0"
  std::snprintf(eb, sizeof eb, "%.*f", decimals, e);
  return std::string(vb) + pm + eb;
}

}  // namespace beverloo
