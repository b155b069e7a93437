#include "core/io/delimited_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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
