#include "core/io/delimited_text.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "core/common/error.h"

namespace lmc::text {
namespace {

TEST(TextFields, ParseDoubleAcceptsOnlyWholeNumbers) {
  EXPECT_EQ(parse_double("12.5"), 12.5);
  EXPECT_EQ(parse_double(" -3e2 "), -300.0);
  EXPECT_EQ(parse_double("+4"), 4.0);
  EXPECT_TRUE(std::isnan(*parse_double("nan")));
  EXPECT_TRUE(std::isnan(*parse_double("NaN")));
  EXPECT_FALSE(parse_double("12abc").has_value());  // never read as 12
  EXPECT_FALSE(parse_double("1.2.3").has_value());
  EXPECT_FALSE(parse_double("").has_value());
  EXPECT_FALSE(parse_double("   ").has_value());
  EXPECT_FALSE(parse_double("1e999").has_value());  // out of range is not silently inf
  EXPECT_FALSE(parse_double("++1").has_value());
  EXPECT_FALSE(parse_double("0x10").has_value());
}

TEST(TextFields, ParseIntAcceptsIntegralDecimalsOnly) {
  EXPECT_EQ(parse_int("2998371808"), 2998371808LL);
  EXPECT_EQ(parse_int("-7"), -7);
  EXPECT_EQ(parse_int("3.0"), 3);  // pandas writes integer columns this way
  EXPECT_FALSE(parse_int("3.5").has_value());
  EXPECT_FALSE(parse_int("12abc").has_value());
  EXPECT_FALSE(parse_int("nan").has_value());
  EXPECT_EQ(parse_int("9223372036854775807"), std::numeric_limits<std::int64_t>::max());
}

TEST(TextFields, ShortestFormatRoundTripsExactly) {
  const double values[] = {0.1, 1.0 / 3.0, -0.0, 69.6427, 1e-300, 5e-324, 1.7976931348623157e308, -123456.789e-5};
  for (const double v : values) {
    const std::string s = format_double(v);
    const auto back = parse_double(s);
    ASSERT_TRUE(back.has_value()) << s;
    EXPECT_EQ(*back, v) << s;
    EXPECT_EQ(std::signbit(*back), std::signbit(v)) << s;
  }
  EXPECT_EQ(format_double(69.6427), "69.6427");
  EXPECT_EQ(format_double(100.0), "100");
  EXPECT_EQ(format_double(-std::numeric_limits<double>::quiet_NaN()), "nan");
}

// Plain decimals take a fast path of their own: it must give the bits std::from_chars gives for
// every string, those it handles and those it hands on (longer digits, exponents, odd forms).
TEST(TextFields, ParseDoubleGivesFromCharsBitsForEveryDecimal) {
  const auto from_chars_value = [](const std::string& s) -> std::optional<double> {
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || ptr != s.data() + s.size()) return std::nullopt;
    return v;
  };
  const auto same = [&](const std::string& s) {
    const auto ours = parse_double(s);
    const auto theirs = from_chars_value(s);
    ASSERT_EQ(ours.has_value(), theirs.has_value()) << s;
    if (!ours) return;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*ours), std::bit_cast<std::uint64_t>(*theirs)) << s;
  };
  for (const char* s : {"0",
                        "-0",
                        "-0.0",
                        "0.5",
                        "007",
                        "1.",
                        ".5",
                        "-.5",
                        "5.e3",
                        "9007199254740992",
                        "9007199254740993",
                        "9007199254740991.5",
                        "0.0000000000000000000001",
                        "1234567890123456789",
                        "12345678901234567890",
                        "-66.71016208025884",
                        "149.4014546349786",
                        "0.1",
                        "0.3",
                        "2.2250738585072014",
                        "1.7976931348623157",
                        "123456.78901234567",
                        "1e22",
                        "-"}) {
    same(s);
  }
  // Random decimals shaped like the recordings' (up to 17 significant digits, any point position)
  // and the measures' (4 decimals).
  std::mt19937_64 rng(20261127);
  for (int n = 0; n < 300000; ++n) {
    std::string s;
    if (rng() % 3 == 0) s += '-';
    const int digits = 1 + static_cast<int>(rng() % 20);
    const int point = static_cast<int>(rng() % (digits + 1));
    for (int d = 0; d < digits; ++d) {
      if (d == point && d > 0) s += '.';
      s += static_cast<char>('0' + rng() % 10);
    }
    same(s);
  }
  for (int n = 0; n < 100000; ++n) {
    const double v = std::uniform_real_distribution<double>(-500.0, 500.0)(rng);
    same(format_double(v));
  }
}

TEST(TextFields, SplitsKeepColumns) {
  std::vector<Field> f;
  split_fields("a\t\tbc\t", '\t', f);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[2].text, "bc");
  EXPECT_EQ(f[2].column, 4);
  EXPECT_EQ(f[3].text, "");
  split_whitespace(" 1   0  x ", f);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[1].text, "0");
  EXPECT_EQ(f[1].column, 6);
}

TEST(TextFields, LinesStripCarriageReturnAndFlagMissingNewline) {
  const auto lines = split_lines("a\r\nb\nc");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "a");
  EXPECT_TRUE(lines[1].has_newline);
  EXPECT_FALSE(lines[2].has_newline);
  EXPECT_EQ(lines[2].number, 3);
}

TEST(TextFields, RejectsNulAndInvalidUtf8WithPosition) {
  EXPECT_NO_THROW(
      require_text("Gr\xC3\xBC\xC3\x9F"
                   "e\n",
                   "f"));  // valid UTF-8 (Grüße)
  try {
    require_text(std::string("ab\ncd\0e", 7), "bin.dat");
    FAIL() << "NUL accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 3);
    EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos);
  }
  try {
    require_text("x\xFF", "latin.txt");
    FAIL() << "invalid UTF-8 accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().column, 2);
  }
  EXPECT_THROW(require_text("\xC0\xAF", "overlong"), Error);
  EXPECT_THROW(require_text("\xED\xA0\x80", "surrogate"), Error);
}

// The check skips plain ASCII a word at a time: a bad byte at every offset of a long text, and a
// valid multi-byte character straddling a word boundary, are judged as byte by byte.
TEST(TextFields, ABadByteIsFoundAtEveryOffsetOfALongText) {
  const std::string line = "1\t2.5\t-3.25\n";  // 12 bytes: lines cross the 8-byte words
  std::string text;
  for (int k = 0; k < 10; ++k) text += line;
  for (size_t at = 0; at < text.size(); ++at) {
    for (const char bad : {'\0', '\xFF'}) {
      std::string t = text;
      t[at] = bad;
      try {
        require_text(t, "t.txt");
        FAIL() << "byte " << static_cast<int>(bad) << " at " << at << " accepted";
      } catch (const Error& e) {
        EXPECT_EQ(e.where().line, static_cast<long>(at / line.size()) + 1) << at;
        EXPECT_EQ(e.where().column, static_cast<long>(at % line.size()) + 1) << at;
      }
    }
  }
  for (size_t at = 0; at + 2 <= text.size(); ++at) {
    std::string t = text;
    t.replace(at, 2, "\xC3\xBC");  // ü
    EXPECT_NO_THROW(require_text(t, "t.txt")) << at;
  }
}

}  // namespace
}  // namespace lmc::text
