// The heatmap primitive (coverage heatmap): one rect per cell, a missing value drawn
// hatched and explained in the legend, labels for every row (per panel) and column, values in
// the cells in a colour that reads on the cell, the colour bar saying what the colour means, and
// nothing written past the document's edges.
#include "core/figures/heatmap_svg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "core/figures/colour_scale.h"
#include "core/figures/svg_marks.h"
#include "tests/core/figures/svg_test_support.h"

namespace lmc::heatmap_svg_test {

using namespace svg_test_support;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Heatmap two_panels() {
  Heatmap h;
  h.title = "Coverage";
  h.rows = {"thumb", "index", "middle"};
  h.columns = {"open hand", "index flexion", "open hand", "index flexion"};
  h.column_groups = {"palm down", "palm down", "palm left", "palm left"};
  h.row_title = "finger";
  h.column_title = "reference pose";
  h.scale_label = "share of frames";
  h.panels.push_back({"at least one", {0, 0.25, 0.5, 1, 0.87, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}});
  h.panels.push_back({"two or more", {0, 0.1, kNan, 0.9, 0.8, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}});
  h.notes = {"A cell: the share of frames."};
  return h;
}

size_t count(const std::vector<std::string>& v, const std::string& s) {
  return static_cast<size_t>(std::count(v.begin(), v.end(), s));
}

TEST(FiguresHeatmap, OneRectPerCellAndTheMissingOneIsMarked) {
  const std::string svg = to_svg(two_panels(), 800, 520);
  EXPECT_EQ(xml_balance_problem(svg), "");
  EXPECT_EQ(attribute_values(svg, "rect class=\"cell\"", "fill").size(), 23u);
  const auto missing = attribute_values(svg, "rect class=\"cell no-data\"", "fill");
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].rfind("url(#", 0), 0u) << missing[0];  // hatched, not a colour of the scale
  // The legend explains the hatch.
  EXPECT_EQ(attribute_values(svg, "rect class=\"legend-no-data\"", "fill").size(), 1u);
  EXPECT_EQ(count(text_contents(svg), "no data"), 1u);
  // Without a missing value there is nothing to explain.
  Heatmap full = two_panels();
  full.panels[1].values[2] = 0.5;
  const std::string svg_full = to_svg(full, 800, 520);
  EXPECT_TRUE(attribute_values(svg_full, "rect class=\"cell no-data\"", "fill").empty());
  EXPECT_EQ(count(text_contents(svg_full), "no data"), 0u);
}

TEST(FiguresHeatmap, EveryRowColumnGroupAndPanelIsLabelled) {
  const auto texts = text_contents(to_svg(two_panels(), 800, 520));
  for (const char* row : {"thumb", "index", "middle"}) EXPECT_EQ(count(texts, row), 2u) << row;  // each panel
  // Column labels once, under the bottom panel ("index flexion" may wrap onto two lines).
  EXPECT_EQ(count(texts, "open hand"), 2u);
  EXPECT_EQ(count(texts, "palm down"), 1u);
  EXPECT_EQ(count(texts, "palm left"), 1u);
  for (const char* s : {"Coverage", "at least one", "two or more", "finger", "reference pose", "share of frames",
                        "A cell: the share of frames."})
    EXPECT_EQ(count(texts, s), 1u) << s;
  // The legend's ticks say what the colours stand for, in the cells' unit.
  for (const char* tick : {"0 %", "50 %", "100 %"}) EXPECT_GE(count(texts, tick), 1u) << tick;
}

TEST(FiguresHeatmap, CellsAreColouredOnTheScaleAndCarryTheirValueReadably) {
  const std::string svg = to_svg(two_panels(), 800, 520);
  const auto fills = attribute_values(svg, "rect class=\"cell\"", "fill");
  EXPECT_EQ(fills[0], svg::hex(sequential_colour(0.0)));
  EXPECT_EQ(fills[3], svg::hex(sequential_colour(1.0)));
  const auto values = text_contents(svg);
  EXPECT_EQ(count(values, "87 %"), 1u);
  // White on the dark end, black on the bright end.
  const auto colours = attribute_values(svg, "text class=\"cell-value\"", "fill");
  ASSERT_EQ(colours.size(), 23u);
  EXPECT_EQ(colours[0], "#ffffff");  // 0 %
  EXPECT_EQ(colours[3], "#000000");  // 100 %
  EXPECT_EQ(attribute_values(svg, "rect class=\"legend-bar\"", "fill").size(), 1u);
  // No value text at all when asked for none.
  Heatmap quiet = two_panels();
  quiet.value_text = HeatmapValueText::none;
  EXPECT_TRUE(attribute_values(to_svg(quiet), "text class=\"cell-value\"", "fill").empty());
}

TEST(FiguresHeatmap, TooManyColumnsForWrappedLabelsTurnsThemUpright) {
  Heatmap h;
  h.rows = {"a"};
  for (int i = 0; i < 40; ++i) h.columns.push_back("column-number-" + std::to_string(i));
  h.panels.push_back({"", std::vector<double>(40, 0.5)});
  const std::string svg = to_svg(h, 800, 400);
  EXPECT_EQ(xml_balance_problem(svg), "");
  const auto transforms = attribute_values(svg, "text class=\"column-label\"", "transform");
  ASSERT_EQ(transforms.size(), 40u);
  EXPECT_NE(transforms[0].find("rotate(-90)"), std::string::npos);
  // Their cells are too narrow for "50 %": no value text rather than text over the neighbours.
  EXPECT_TRUE(attribute_values(svg, "text class=\"cell-value\"", "fill").empty());
}

TEST(FiguresHeatmap, TextStaysInsideTheDocument) {
  for (const int w : {420, 800, 1200}) {
    const std::string svg = to_svg(two_panels(), w, 520);
    const auto xs = attribute_values(svg, "text", "x");
    const auto anchors = attribute_values(svg, "text", "text-anchor");
    const auto texts = text_contents(svg);
    ASSERT_EQ(xs.size(), texts.size());
    for (size_t i = 0; i < xs.size(); ++i) {
      const double x = std::stod(xs[i]);
      if (x == 0) continue;  // rotated text is placed by its transform
      const double width = 0.6 * 12 * static_cast<double>(texts[i].size());
      const double left = anchors[i] == "end" ? x - width : anchors[i] == "middle" ? x - width / 2 : x;
      EXPECT_GE(left, 0) << w << " " << texts[i];
      EXPECT_LE(left + width, w + 0.01) << w << " " << texts[i];
    }
  }
}

TEST(FiguresHeatmap, SameHeatmapSameBytes) {
  EXPECT_EQ(to_svg(two_panels()), to_svg(two_panels()));
}

}  // namespace lmc::heatmap_svg_test
