#include "core/figures/figure_csv.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace lmc::figure_csv_test {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> csv_lines(const std::string& csv) {
  std::vector<std::string> out;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The cells of an unquoted line.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out(1);
  for (const char c : line) {
    if (c == ',')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

double read_cell(const std::string& cell) {
  double v = kNan;
  std::from_chars(cell.data(), cell.data() + cell.size(), v);
  return v;
}

TEST(FiguresCsv, MissingValuesAreEmptyCellsAndNumbersReadBackExactly) {
  Figure f;
  f.series.push_back({"angle", {}, SeriesStyle::line, {0.0, 0.1, 0.2, 0.3}, {1.0 / 3.0, kNan, -2.5e-7, 0.0}});
  f.series.push_back({"other", {}, SeriesStyle::points, {1, kNan, 3}, {std::numeric_limits<double>::infinity(), 4, 5}});
  const auto lines = csv_lines(to_csv(f));
  ASSERT_EQ(lines.size(), 1u + 4u + 3u);
  EXPECT_EQ(lines[0], "series,x,y");
  EXPECT_EQ(lines[2], "angle,0.1,");   // NaN: empty, never 0
  EXPECT_EQ(lines[4], "angle,0.3,0");  // a real 0 stays 0
  EXPECT_EQ(lines[5], "other,1,");
  EXPECT_EQ(lines[6], "other,,4");
  // Every row equals the plotted sample exactly.
  size_t row = 1;
  for (const Series& s : f.series)
    for (size_t i = 0; i < s.x.size(); ++i, ++row) {
      const auto c = cells(lines[row]);
      ASSERT_EQ(c.size(), 3u) << lines[row];
      EXPECT_EQ(c[0], s.name);
      for (const auto& [cell, value] : {std::pair{c[1], s.x[i]}, std::pair{c[2], s.y[i]}}) {
        if (std::isfinite(value)) {
          EXPECT_EQ(read_cell(cell), value) << lines[row];
        } else {
          EXPECT_EQ(cell, "") << lines[row];
        }
      }
    }
}

TEST(FiguresCsv, ASeriesShorterInYHasEmptyCellsForTheRest) {
  Figure f;
  f.series.push_back({"s", {}, SeriesStyle::line, {1, 2, 3}, {4}});
  EXPECT_EQ(to_csv(f), "series,x,y\ns,1,4\ns,2,\ns,3,\n");
}

TEST(FiguresCsv, NamesWithCommasOrQuotesAreQuoted) {
  EXPECT_EQ(csv_field("plain name"), "plain name");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
}

TEST(FiguresCsv, AGridNumbersItsPanelsFromOne) {
  FigureGrid g;
  for (int p = 0; p < 2; ++p) {
    Figure f;
    f.series.push_back({"s" + std::to_string(p), {}, SeriesStyle::line, {0.5}, {1.0 * p}});
    g.panels.push_back(f);
  }
  EXPECT_EQ(to_csv(g), "panel,series,x,y\n1,s0,0.5,0\n2,s1,0.5,1\n");
}

TEST(FiguresCsv, AHeatmapHasACellARowWithItsGroupAndAnEmptyCellForNoData) {
  Heatmap h;
  h.rows = {"thumb", "index"};
  h.columns = {"open hand", "open hand"};
  h.column_groups = {"palm down", "palm left"};
  h.panels = {{"1+", {0.25, 1, kNan, 0.1}}, {"2+", {0, 0.5}}};  // the second is short: no data
  const auto lines = csv_lines(to_csv(h));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[0], "panel,row,column_group,column,value");
  EXPECT_EQ(lines[1], "1,thumb,palm down,open hand,0.25");
  EXPECT_EQ(lines[2], "1,thumb,palm left,open hand,1");
  EXPECT_EQ(lines[3], "1,index,palm down,open hand,");
  EXPECT_EQ(lines[4], "1,index,palm left,open hand,0.1");
  EXPECT_EQ(lines[6], "2,thumb,palm left,open hand,0.5");
  EXPECT_EQ(lines[8], "2,index,palm left,open hand,");
  h.column_groups.clear();
  EXPECT_EQ(csv_lines(to_csv(h))[1], "1,thumb,,open hand,0.25");
}

}  // namespace lmc::figure_csv_test
