#include "core/common/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/common/decimal_digits.h"

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

// format_fixed writes through std::to_chars for speed; every output file depends on it writing
// exactly what printf's "%.*f" writes, ties and huge values included.
TEST(NumberFormat, FixedWritesWhatPrintfWrites) {
  const auto printf_fixed = [](double v, int decimals) {
    std::string out(512, '\0');
    out.resize(static_cast<size_t>(std::snprintf(out.data(), out.size(), "%.*f", decimals, v)));
    return out;
  };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 12), digits(0, 9);
  for (int k = 0; k < 200'000; ++k) {
    const double v = std::ldexp(mantissa(rng), exponent(rng) * 3);
    const int d = digits(rng);
    ASSERT_EQ(format_fixed(v, d), printf_fixed(v, d)) << "v = " << v << ", " << d << " decimals";
  }
  // Halfway cases: printf rounds the exact binary value, so 0.125 → "0.12" and 2.675 → "2.67".
  for (const double v : {0.125, 0.375, 2.5, 3.5, -0.5, 2.675, 1.005, 1e15 + 0.5, 0.0, -0.0})
    for (int d = 0; d <= 3; ++d) EXPECT_EQ(format_fixed(v, d), printf_fixed(v, d)) << v << " " << d;
  // Every binary exponent and every decimal count the integer path covers, and its edges: ties at
  // each decimal, the largest values it takes and the first it hands on, subnormals, signed zeros.
  std::uniform_int_distribution<int> any_exponent(-1074, 64);
  for (int k = 0; k < 300'000; ++k) {
    const double v = std::ldexp(mantissa(rng), any_exponent(rng));
    const int d = digits(rng);
    ASSERT_EQ(format_fixed(v, d), printf_fixed(v, d)) << "v = " << v << ", " << d << " decimals";
  }
  for (int d = 0; d <= 9; ++d) {
    const double unit = std::pow(10.0, -d);
    for (const double v : {0.5 * unit, 1.5 * unit, 2.5 * unit, -0.5 * unit, 9.2e18 / std::pow(10.0, d),
                           9.3e18 / std::pow(10.0, d), 1e19, 4.9e-324, -4.9e-324, 2.2250738585072014e-308, -0.0, 0.0,
                           0.99999999995, 9.99999999995, -9.99999999995, 123456.78905, 0.00005})
      EXPECT_EQ(format_fixed(v, d), printf_fixed(v, d)) << v << " " << d;
  }
  // Longer than the fast path's buffer: written whole, never cut.
  EXPECT_EQ(format_fixed(1e300, 4), printf_fixed(1e300, 4));
  EXPECT_EQ(format_fixed(-std::numeric_limits<double>::max(), 2), printf_fixed(-std::numeric_limits<double>::max(), 2));
}

// The sixteen-digit writer behind both number writers: every digit, leading zeros included, as
// printf writes them, at the edges of each group of four and eight and at random.
TEST(NumberFormat, SixteenDigitsAreWrittenAsPrintfWritesThem) {
  std::vector<std::uint64_t> values = {0, 1, 9, 10, 99, 100, 9999, 10000, 99999999, 100000000, 9999999999999999u};
  for (std::uint64_t p = 1; p < 10000000000000000u; p *= 10) {
    values.push_back(p - 1);
    values.push_back(p);
    values.push_back(p + 1);
  }
  std::mt19937_64 rng(16);
  for (int k = 0; k < 200'000; ++k) values.push_back(rng() % 10000000000000000u);
  for (const std::uint64_t v : values) {
    char ours[17] = {};
    decimal_digits::write_sixteen_digits(ours, v);
    char expected[32];
    std::snprintf(expected, sizeof expected, "%016llu", static_cast<unsigned long long>(v));
    ASSERT_EQ(std::string(ours, 16), std::string(expected)) << v;
  }
}

}  // namespace lmc::number_format_test
