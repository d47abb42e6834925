// Values printed rounded to their errors (issue 18): one or two significant digits of the
// error, the value to the same decimal place.
#include <gtest/gtest.h>

#include <cmath>

#include "reports/number_format.h"

namespace beverloo {
namespace {

TEST(NumberFormat, ValueIsRoundedToItsError) {
  EXPECT_EQ(format_with_error(3.348519142, 0.3933371156), "3.3 ± 0.4");
  EXPECT_EQ(format_with_error(1.267568324, 0.2311682639), "1.27 ± 0.23");  // leading 2: two digits
  EXPECT_EQ(format_with_error(0.004697518545, 0.006062939038), "0.005 ± 0.006");
  EXPECT_EQ(format_with_error(123.4, 45.6), "120 ± 50");
  EXPECT_EQ(format_with_error(-0.04, 0.1), "-0.04 ± 0.10");
  EXPECT_EQ(format_with_error(0.001, 0.3), "0.0 ± 0.3") << "no -0.0 and no spurious digits";
  EXPECT_EQ(format_with_error(7.8675, 0.0987), "7.87 ± 0.10") << "0.099 rounds to 0.10";
}

TEST(NumberFormat, MissingOrZeroErrorsGiveTheValueAlone) {
  EXPECT_EQ(format_with_error(2.5, 0), "2.5");
  EXPECT_EQ(format_with_error(2.5, NAN), "2.5");
  EXPECT_EQ(format_with_error(INFINITY, 1), "inf");
  EXPECT_EQ(format_value(0.000123456), "0.000123");
}

}  // namespace
}  // namespace beverloo
