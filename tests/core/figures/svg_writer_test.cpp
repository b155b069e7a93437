#include "core/figures/svg_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <locale>
#include <string>

#include "core/figures/locale_free_number.h"
#include "tests/core/figures/svg_test_support.h"

namespace lmc::svg_writer_test {

using namespace svg_test_support;

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();

Figure gap_figure() {
  Figure f;
  f.title = "Angle";
  f.x = {"time", "s", AxisRange{0.0, 4.0}};
  f.y = {"angle", "deg", AxisRange{-10.0, 10.0}};
  f.series.push_back({"index MCP", std::nullopt, SeriesStyle::line, {0, 1, 2, 3, 4}, {5, 6, kGap, 7, 8}, true});
  return f;
}

// The y pixel of a value, read from the plot frame and the fixed range of gap_figure().
double frame_value(const std::string& svg, const std::string& attr) {
  const auto v = attribute_values(svg, "rect class=\"frame\"", attr);
  return v.empty() ? std::nan("") : std::stod(v.front());
}

TEST(FiguresSvg, AMissingSampleSplitsTheLineIntoTwoPiecesAndIsNeverDrawnAtZero) {
  const std::string svg = to_svg(gap_figure(), 800, 500);
  const auto pieces = attribute_values(svg, "path class=\"line\"", "d");
  ASSERT_EQ(pieces.size(), 2u) << svg;
  const double top = frame_value(svg, "y"), h = frame_value(svg, "height");
  const double y_of_zero = top + h / 2;  // the range is [-10, 10]
  for (const std::string& d : pieces) {
    const auto n = path_numbers(d);
    ASSERT_EQ(n.size(), 4u) << d;  // two samples per piece
    for (size_t i = 1; i < n.size(); i += 2) EXPECT_GT(std::abs(n[i] - y_of_zero), 10.0) << d;
  }
  // The gap band is there, between samples 1 and 3.
  EXPECT_EQ(attribute_values(svg, "rect class=\"gap\"", "width").size(), 1u);
}

TEST(FiguresSvg, OnlyMissingAtTheEdgesLeavesOnePieceAndNoBand) {
  Figure f = gap_figure();
  f.series[0].y = {kGap, 1, 2, 3, std::numeric_limits<double>::infinity()};
  const std::string svg = to_svg(f, 600, 400);
  EXPECT_EQ(attribute_values(svg, "path class=\"line\"", "d").size(), 1u);
  EXPECT_TRUE(attribute_values(svg, "rect class=\"gap\"", "width").empty());
}

TEST(FiguresSvg, TextFromFilesIsEscapedAndTheDocumentIsBalanced) {
  Figure f = gap_figure();
  f.title = "a<b & \"c\" 'd'>";
  f.series[0].name = "</text><script>x</script>";
  f.x.label = "t&t";
  f.references.push_back({1.0, "bias <1>", Dash::dashed});
  f.notes.push_back("n = 3 & \"quoted\"\x01 end");
  const std::string svg = to_svg(f);
  EXPECT_EQ(xml_balance_problem(svg), "") << svg;
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;"), std::string::npos);
  EXPECT_NE(svg.find("&lt;/text&gt;&lt;script&gt;"), std::string::npos);
  EXPECT_NE(svg.find("t&amp;t (s)"), std::string::npos);
  EXPECT_NE(svg.find("bias &lt;1&gt;"), std::string::npos);
  EXPECT_EQ(svg.find('\x01'), std::string::npos);
}

TEST(FiguresSvg, IsAStandaloneSvgWithTitleAxisLabelsUnitsAndTicks) {
  const std::string svg = to_svg(gap_figure());
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"", 0), 0u);
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_NE(svg.find("version=\"1.1\""), std::string::npos);
  const auto texts = text_contents(svg);
  const auto has = [&](const std::string& s) { return std::find(texts.begin(), texts.end(), s) != texts.end(); };
  EXPECT_TRUE(has("Angle"));
  EXPECT_TRUE(has("time (s)"));
  EXPECT_NE(svg.find(">angle (deg)</text>"), std::string::npos);
  EXPECT_TRUE(has("index MCP"));
  for (const char* tick : {"-10", "0", "10"}) EXPECT_TRUE(has(tick)) << tick;  // y: steps of 2 or 5
  EXPECT_TRUE(has("4") || has("4.0"));                                         // x: of 1 or 0.5
  EXPECT_NE(svg.find("clip-path=\"url(#plot-clip-0)\""), std::string::npos);
  EXPECT_NE(svg.find("<clipPath id=\"plot-clip-0\">"), std::string::npos);
}

TEST(FiguresSvg, TheLegendIsOutsideThePlotArea) {
  Figure f = gap_figure();
  for (int i = 0; i < 6; ++i)
    f.series.push_back({"series number " + std::to_string(i), {}, SeriesStyle::points, {1}, {1}});
  const std::string svg = to_svg(f, 500, 400);
  const double top = frame_value(svg, "y");
  // Legend labels are the texts with the series' names: all above the plot frame.
  const auto ys = attribute_values(svg, "text", "y");
  const auto texts = text_contents(svg);
  ASSERT_EQ(ys.size(), texts.size());
  int legend = 0;
  for (size_t i = 0; i < texts.size(); ++i)
    if (texts[i].rfind("series number", 0) == 0 || texts[i] == "index MCP") {
      EXPECT_LT(std::stod(ys[i]), top) << texts[i];
      ++legend;
    }
  EXPECT_EQ(legend, 7);
}

TEST(FiguresSvg, PointsAreCirclesAndReferenceLinesAreDashedWithTheirLabel) {
  Figure f;
  f.x = {"mean", "deg", {}};
  f.y = {"difference", "deg", {}};
  f.series.push_back({"pairs", {}, SeriesStyle::points, {1, 2, kGap, 4}, {0.5, -0.5, 1, 0.25}});
  f.references.push_back({0.1, "bias 0.10", Dash::dashed});
  f.references.push_back({1.2, "+1.96 SD", Dash::dotted});
  f.references.push_back({-1.0, "-1.96 SD", Dash::dotted});
  const std::string svg = to_svg(f);
  EXPECT_EQ(attribute_values(svg, "circle class=\"point\"", "cx").size(), 3u);
  EXPECT_TRUE(attribute_values(svg, "path class=\"line\"", "d").empty());
  const auto dashes = attribute_values(svg, "line class=\"reference\"", "stroke-dasharray");
  EXPECT_EQ(dashes, (std::vector<std::string>{"6 4", "2 3", "2 3"}));
  const auto texts = text_contents(svg);
  for (const char* label : {"bias 0.10", "+1.96 SD", "-1.96 SD"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), label), texts.end()) << label;
  // The fitted y range holds the reference lines.
  const auto ry = attribute_values(svg, "line class=\"reference\"", "y1");
  const double top = frame_value(svg, "y"), h = frame_value(svg, "height");
  for (const auto& y : ry) {
    EXPECT_GT(std::stod(y), top);
    EXPECT_LT(std::stod(y), top + h);
  }
}

TEST(FiguresSvg, OutputIsDeterministicAndUsesDefaultPaletteColours) {
  Figure f = gap_figure();
  f.series.push_back({"second", {}, SeriesStyle::line, {0, 1}, {1, 2}});
  EXPECT_EQ(to_svg(f), to_svg(f));
  EXPECT_NE(to_svg(f).find("stroke=\"#e69f00\""), std::string::npos);  // Okabe–Ito orange
  EXPECT_NE(to_svg(f).find("stroke=\"#56b4e9\""), std::string::npos);  // sky blue
}

// A decimal comma, for when no such named locale is installed.
struct CommaPoint : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
};

TEST(FiguresSvg, NumbersIgnoreTheGlobalLocale) {
  std::locale comma(std::locale::classic(), new CommaPoint);
  try {
    comma = std::locale("de_DE.UTF-8");  // also switches the C library's locale (printf)
  } catch (const std::exception&) {
  }
  const std::string before = to_svg(gap_figure());
  const std::locale old = std::locale::global(comma);
  const std::string during = to_svg(gap_figure());
  std::locale::global(old);
  EXPECT_EQ(before, during);
}

TEST(FiguresSvg, NumbersAreWrittenInFixedPrecision) {
  EXPECT_EQ(fixed_c(1.5, 2), "1.50");
  EXPECT_EQ(fixed_c(-0.001, 2), "0.00");
  EXPECT_EQ(fixed_c(std::nan(""), 2), "nan");
  EXPECT_EQ(exact_c(0.1), "0.1");
  EXPECT_EQ(exact_c(std::nan("")), "");
}

TEST(FiguresSvg, AGridStacksPanelsOnOneXAxisLabelledOnce) {
  FigureGrid g;
  g.title = "Trial 3";
  g.x = {"time", "s", {}};
  for (int p = 0; p < 3; ++p) {
    Figure f;
    f.title = "panel " + std::to_string(p);
    f.y = {"angle " + std::to_string(p), "deg", {}};
    f.series.push_back({"A", {}, SeriesStyle::line, {0, 1, 2}, {1.0 * p, 2, kGap}});
    f.series.push_back({"B", {}, SeriesStyle::line, {0, 1, 2, 3}, {0, 1, 0, 1}});
    g.panels.push_back(f);
  }
  const std::string svg = to_svg(g, 700, 900);
  EXPECT_EQ(xml_balance_problem(svg), "");
  const auto texts = text_contents(svg);
  EXPECT_EQ(std::count(texts.begin(), texts.end(), "time (s)"), 1);
  EXPECT_EQ(attribute_values(svg, "clipPath", "id"),
            (std::vector<std::string>{"plot-clip-0", "plot-clip-1", "plot-clip-2"}));
  // Same x: every panel's frame starts and ends at the same pixels, and the panels do not overlap.
  const auto xs = attribute_values(svg, "rect class=\"frame\"", "x");
  const auto ws = attribute_values(svg, "rect class=\"frame\"", "width");
  const auto ys = attribute_values(svg, "rect class=\"frame\"", "y");
  const auto hs = attribute_values(svg, "rect class=\"frame\"", "height");
  ASSERT_EQ(xs.size(), 3u);
  for (size_t i = 1; i < 3; ++i) {
    EXPECT_EQ(xs[i], xs[0]);
    EXPECT_EQ(ws[i], ws[0]);
    EXPECT_GT(std::stod(ys[i]), std::stod(ys[i - 1]) + std::stod(hs[i - 1]));
  }
  EXPECT_LT(std::stod(ys[2]) + std::stod(hs[2]), 900.0);
}

TEST(FiguresSvg, ALonePresentSampleOfALineIsADot) {
  Figure f = gap_figure();
  f.series[0].y = {1, kGap, 2, kGap, kGap};
  const std::string svg = to_svg(f);
  EXPECT_TRUE(attribute_values(svg, "path class=\"line\"", "d").empty());
  EXPECT_EQ(attribute_values(svg, "circle class=\"lone\"", "cx").size(), 2u);
}

TEST(FiguresSvg, AFigureWithNoDataOrOnlyMissingDataIsStillAValidDocument) {
  Figure empty;
  EXPECT_EQ(xml_balance_problem(to_svg(empty)), "");
  Figure missing;
  missing.series.push_back({"all missing", {}, SeriesStyle::line_and_points, {kGap, 1}, {2, kGap}});
  const std::string svg = to_svg(missing, 10, 10);  // too small: raised to 240 x 160
  EXPECT_EQ(xml_balance_problem(svg), "");
  EXPECT_NE(svg.find("width=\"240\" height=\"160\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"point\""), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(xml_balance_problem(to_svg(FigureGrid{})), "");
}

}  // namespace lmc::svg_writer_test
