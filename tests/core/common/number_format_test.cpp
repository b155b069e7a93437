#include "core/common/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lmc::number_format_test {

TEST(NumberFormat, ReadableNeverWritesANegativeZero) {
  EXPECT_EQ(format_readable(-0.04, 1), "0.0");
  EXPECT_EQ(format_readable(-0.004, 2, true), "0.00");
  EXPECT_EQ(format_readable(-0.0, 0, true), "0");
  EXPECT_EQ(format_readable(0.04, 1, true), "0.0");  // a zero has no sign either way
  // Values that do not round to zero keep their sign.
  EXPECT_EQ(format_readable(-0.05, 1), "-0.1");
  EXPECT_EQ(format_readable(-2.14, 1, true), "-2.1");
  EXPECT_EQ(format_readable(0.25, 2, true), "+0.25");
  EXPECT_EQ(format_readable(13.0, 1), "13.0");
  EXPECT_EQ(format_readable(std::nan(""), 1), "nan");
  EXPECT_EQ(format_readable(-std::numeric_limits<double>::infinity(), 1), "-inf");
}

TEST(NumberFormat, FixedKeepsThePythonStyleOfTheStudyOutputs) {
  // The study's text outputs keep printf's form: only the readable form drops the sign.
  EXPECT_EQ(format_fixed(-0.004, 2), "-0.00");
}

}  // namespace lmc::number_format_test
