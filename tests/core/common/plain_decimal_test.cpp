#include "core/common/plain_decimal.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

namespace lmc::plain_decimal_test {

// Compares read_plain_decimal with std::from_chars on texts: where ours reads a number, it must be
// the same double (bit for bit) ending at the same character. Counts how often ours declines.
struct Comparison {
  long checked = 0;
  long declined = 0;
  long differing = 0;
  void check(const std::string& text) {
    ++checked;
    double ours = 0.0;
    const char* end = read_plain_decimal(text.data(), text.data() + text.size(), ours);
    if (end == nullptr) {
      ++declined;
      return;
    }
    double standard = 0.0;
    const auto [standard_end, ec] = std::from_chars(text.data(), text.data() + text.size(), standard);
    const bool same = ec == std::errc{} && standard_end == end &&
                      std::bit_cast<std::uint64_t>(standard) == std::bit_cast<std::uint64_t>(ours);
    if (!same && ++differing <= 5) {
      ADD_FAILURE() << "'" << text << "': ours " << std::hexfloat << ours << " ending at " << end - text.data()
                    << ", std::from_chars " << standard << " ending at " << standard_end - text.data();
    }
  }
};

std::string shortest(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}
std::string shortest(float v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}
std::string with_precision(double v, int significant) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

// 1 to `max_digits` random digits with the point anywhere (or none), either sign, leading zeros
// included.
std::string random_digits(std::mt19937_64& rng, int max_digits) {
  const int digits = 1 + static_cast<int>(rng() % static_cast<unsigned>(max_digits));
  std::string s = rng() % 2 ? "-" : "";
  const int point = static_cast<int>(rng() % static_cast<unsigned>(digits + 1));
  for (int d = 0; d < digits; ++d) {
    if (d == point && d > 0) s += '.';
    s += static_cast<char>('0' + rng() % 10);
  }
  return s;
}

TEST(PlainDecimal, ReadsTheNumbersOfRecordingsAndTrcFilesAsFromCharsDoes) {
  double v = 0.0;
  const std::string text = "149.41004537989676\t-2.98976";
  const char* end = read_plain_decimal(text.data(), text.data() + text.size(), v);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(*end, '\t');
  EXPECT_EQ(v, 149.41004537989676);
  end = read_plain_decimal(end + 1, text.data() + text.size(), v);
  ASSERT_EQ(end, text.data() + text.size());
  EXPECT_EQ(v, -2.98976);

  Comparison c, small;
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> coordinate(-400.0, 400.0);
  for (int i = 0; i < 300000; ++i) {
    const double x = coordinate(rng);
    c.check(shortest(x));                       // our simulator and recorder: up to 17 digits
    c.check(shortest(static_cast<float>(x)));   // a float's shortest form
    c.check(with_precision(x, 8));              // Vicon's TRC export
    c.check(with_precision(x, 6));              // the study's recordings
    small.check(with_precision(x * 1e-3, 17));  // metres: with the leading zeros often over 19 digits
  }
  EXPECT_EQ(c.differing, 0) << "of " << c.checked;
  EXPECT_EQ(small.differing, 0) << "of " << small.checked;
  // The quick path must be the common one, or it buys nothing: only a number whose product lands
  // near a halfway point between two doubles is declined (about 1 in 2000).
  EXPECT_LT(c.declined, c.checked / 1000) << "declined " << c.declined << " of " << c.checked;
}

TEST(PlainDecimal, ReadsEveryNumberOfUpToFiveDigitsAsFromCharsDoes) {
  // Short numbers go through the same 64-bit product as long ones (plain_decimal.h): every one of
  // them, with the point at every place and either sign.
  Comparison c;
  for (int n = 0; n < 100000; ++n) {
    const std::string digits = std::to_string(n);
    for (size_t point = 0; point < digits.size(); ++point) {
      const std::string text = point == 0 ? digits : digits.substr(0, point) + "." + digits.substr(point);
      c.check(text);
      c.check("-" + text);
      if (point == 0) c.check("0." + text);
    }
  }
  EXPECT_EQ(c.differing, 0) << "of " << c.checked;
  EXPECT_LT(c.declined, c.checked / 500) << "declined " << c.declined << " of " << c.checked;
}

TEST(PlainDecimal, AgreesOnRandomDigitStringsAndOnHalfwayIntegers) {
  Comparison c;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 400000; ++i) {
    c.check(random_digits(rng, 19));
  }
  // Integers halfway between two doubles (2^53 + odd, and the like up to 10^19): from_chars rounds
  // them to even; these are where a double rounding could go wrong.
  for (int shift = 0; shift <= 10; ++shift) {
    for (int i = 0; i < 20000; ++i) {
      const std::uint64_t spacing = std::uint64_t{1} << (shift + 1);  // between doubles in [2^(53+shift), ...)
      const std::uint64_t base = (std::uint64_t{1} << (53 + shift)) + (rng() % (std::uint64_t{1} << 40)) * spacing;
      for (const std::uint64_t n : {base + spacing / 2, base + spacing / 2 - 1, base + spacing / 2 + 1}) {
        if (n >= 10000000000000000000ull) continue;
        c.check(std::to_string(n));
        c.check(std::to_string(n / 10) + "." + std::to_string(n % 10));
      }
    }
  }
  EXPECT_EQ(c.differing, 0) << "of " << c.checked;
  EXPECT_GT(c.checked - c.declined, c.checked / 2);
}

TEST(PlainDecimal, DeclinesWhatIsNotAPlainDecimalOfAtMost19Digits) {
  double v = 42.0;
  for (const std::string s : {"", "-", ".5", "5.", "+1", " 1", "1e5", "1.5E-3", "1.2.3", "nan", "inf", "-inf",
                              "12345678901234567890", "1234567890.1234567890", "x1"}) {
    EXPECT_EQ(read_plain_decimal(s.data(), s.data() + s.size(), v), nullptr) << "'" << s << "'";
    EXPECT_EQ(v, 42.0) << "'" << s << "' changed the output";
  }
  // It stops at anything else, the way from_chars does: the caller checks the separator.
  const std::string triplet = "1.5,-0,7";
  const char* end = read_plain_decimal(triplet.data(), triplet.data() + triplet.size(), v);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(*end, ',');
  EXPECT_EQ(v, 1.5);
  end = read_plain_decimal(end + 1, triplet.data() + triplet.size(), v);
  ASSERT_NE(end, nullptr);
  EXPECT_TRUE(std::signbit(v) && v == 0.0) << "-0 keeps its sign";
}

// The reader that looks ahead in its buffer (16 digits at a time on a CPU with AVX2) must end where
// the digit loop ends and give the same bits, or decline alike and leave the output alone: for every
// text, whatever follows the field in the buffer (a separator, more digits, an exponent, a point)
// and wherever the field's end is put, the digits included. (On a CPU without AVX2 both sides are
// the digit loop, as both sides of the palm hull's four-at-a-time test are its plain form.)
TEST(PlainDecimal, LookingAheadInTheBufferReadsWhatTheDigitLoopReads) {
  std::mt19937_64 rng(28);
  std::uniform_real_distribution<double> coordinate(-400.0, 400.0);
  const std::string after[] = {"\t", ",", "", "7", "e5", ".", "\t1.5", "\n"};
  long compared = 0, differing = 0, read = 0;
  const auto compare = [&](const std::string& field) {
    for (const std::string& next : after) {
      std::string buffer = field + next;
      const size_t padding = buffer.size() + 80;
      buffer.resize(padding, '9');  // digits up to the buffer's end: nothing past `last` may be read
      for (size_t cut = 0; cut <= field.size(); cut += field.size() < 4 ? 1 : field.size() - 2) {
        const size_t length = field.size() - cut;
        const char* first = buffer.data();
        const char* last = first + length;
        double loop = 42.0, ahead = 42.0;
        const char* loop_end = read_plain_decimal(first, last, loop);
        const char* ahead_end = read_plain_decimal(first, last, buffer.data() + buffer.size(), ahead);
        ++compared;
        read += loop_end != nullptr ? 1 : 0;
        const bool same =
            loop_end == ahead_end && std::bit_cast<std::uint64_t>(loop) == std::bit_cast<std::uint64_t>(ahead);
        if (!same && ++differing <= 5) {
          ADD_FAILURE() << "'" << buffer.substr(0, length) << "' (then '" << buffer.substr(length, 8)
                        << "…'): the digit loop gives " << loop << " ending at " << (loop_end ? loop_end - first : -1)
                        << ", looking ahead " << ahead << " ending at " << (ahead_end ? ahead_end - first : -1);
        }
      }
    }
  };
  for (int i = 0; i < 40000; ++i) {
    const double x = coordinate(rng);
    compare(shortest(x));
    compare(with_precision(x, 6));
    compare(with_precision(x * 1e-3, 17));
    compare(random_digits(rng, 22));
  }
  for (const std::string s :
       {"", "-", ".5", "5.", "+1", "0", "-0", "1e5", "nan", "1234567890123456", "12345678901234567",
        "1234567890123456.123", "0.1234567890123456789", "1.2.3", "-.", "99999999999999999999"}) {
    compare(s);
  }
  EXPECT_EQ(differing, 0) << "of " << compared;
  EXPECT_GT(read, compared / 3) << "the comparison must cover numbers read, not only declined ones";
}

}  // namespace lmc::plain_decimal_test
