#include "core/common/shortest_double.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

namespace lmc::shortest_double_test {

std::string ours(double v) {
  char buf[kShortestDoubleMaxChars];
  return std::string(buf, write_shortest(buf, v));
}

std::string standard(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Counts the values written differently from std::to_chars; the first few are reported by value.
struct Comparison {
  long checked = 0;
  long differing = 0;
  void check(double v) {
    ++checked;
    const std::string a = ours(v);
    const std::string b = standard(v);
    if (a == b) return;
    if (++differing <= 5) ADD_FAILURE() << std::hexfloat << v << ": ours " << a << ", std::to_chars " << b;
  }
};

TEST(ShortestDouble, WritesWhatToCharsWritesForTheValuesOfTheStudysFiles) {
  EXPECT_EQ(ours(-0.427388950897086), "-0.427388950897086");
  EXPECT_EQ(ours(149.35698053209168), "149.35698053209168");
  EXPECT_EQ(ours(250.0), "250");
  EXPECT_EQ(ours(0.1), "0.1");
  EXPECT_EQ(ours(-0.0), "-0");
  EXPECT_EQ(ours(0.0), "0");
  EXPECT_EQ(ours(100.0), "100");
  EXPECT_EQ(ours(100000.0), "1e+05");  // shorter than "100000": std::to_chars' rule, kept
  EXPECT_EQ(ours(0.0001234), "0.0001234");
  EXPECT_EQ(ours(0.00001234), "1.234e-05");
  EXPECT_EQ(ours(std::nan("")), standard(std::nan("")));
  EXPECT_EQ(ours(-std::nan("")), standard(-std::nan("")));
  EXPECT_EQ(ours(std::nan("")), "nan");
  EXPECT_EQ(ours(-std::numeric_limits<double>::infinity()), "-inf");

  Comparison c;
  std::mt19937_64 rng(20261128);
  // Millimetres and degrees as the fused and resampled files hold them.
  std::uniform_real_distribution<double> coordinate(-1000.0, 1000.0);
  for (int i = 0; i < 300000; ++i) c.check(coordinate(rng));
  // Short decimals (a sensor's own rounding, Vicon's) and the doubles either side of them.
  for (int i = 0; i < 100000; ++i) {
    const double v = static_cast<double>(static_cast<std::int64_t>(rng() % 2000001) - 1000000) /
                     std::pow(10.0, static_cast<double>(rng() % 8));
    c.check(v);
    c.check(std::nextafter(v, 1e300));
    c.check(std::nextafter(v, -1e300));
  }
  EXPECT_EQ(c.differing, 0) << "of " << c.checked;
}

TEST(ShortestDouble, WritesWhatToCharsWritesAcrossEveryExponent) {
  Comparison c;
  std::mt19937_64 rng(7);
  // Any bit pattern: NaNs (either sign, any payload) have their own short path; subnormals, huge
  // and tiny values take the general route, the rest the fast one; all must agree with std::to_chars.
  for (int i = 0; i < 200000; ++i) c.check(std::bit_cast<double>(rng()));
  // Magnitudes from 1e-8 to 1e17 uniformly in the exponent, with both signs: the fast path's
  // edges (7.6e-6 and 2^53) and the switch from fixed to scientific.
  std::uniform_real_distribution<double> decade(-8.0, 17.0);
  for (int i = 0; i < 100000; ++i) {
    const double v = std::pow(10.0, decade(rng));
    c.check(v);
    c.check(-v);
    c.check(std::nextafter(v, 0.0));
  }
  // Integers (exactly as std::to_chars writes them, up to 2^64) and halves.
  for (int i = 0; i < 100000; ++i) {
    const double v = static_cast<double>(rng() >> (rng() % 64));
    c.check(v);
    c.check(v + 0.5);
  }
  // Powers of two (a lopsided interval), of ten, and their neighbours.
  for (int e = -1074; e < 1024; ++e) {
    c.check(std::ldexp(1.0, e));
    c.check(std::ldexp(3.0, e));
    c.check(std::ldexp(5.0, e));
  }
  for (int e = -30; e <= 30; ++e) {
    const double v = std::pow(10.0, e);
    c.check(v);
    c.check(std::nextafter(v, 0.0));
    c.check(std::nextafter(v, 1e300));
    c.check(5 * v);
  }
  EXPECT_EQ(c.differing, 0) << "of " << c.checked;
}

}  // namespace lmc::shortest_double_test
