// The plot widget's logic without ImGui: min-max decimation against brute force, gaps
// never bridged, linked x ranges, round ticks and the y range fitted to what is visible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ui/model/plot/axis_ticks.h"
#include "ui/model/plot/linked_x_range.h"
#include "ui/model/plot/min_max_decimation.h"

namespace lmc::ui {
namespace plot_model_test {

constexpr double kPlotNaN = std::numeric_limits<double>::quiet_NaN();

TEST(MinMaxDecimation, EveryColumnHoldsTheBruteForceMinimumAndMaximum) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0, 3);
  const int n = 100000, columns = 640;
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[static_cast<size_t>(i)] = i * 0.01;
    y[static_cast<size_t>(i)] = std::sin(i * 0.001) * 40 + noise(rng) + (i == 4321 ? 500.0 : 0.0);  // one spike
  }
  const double lo = 100.0, hi = 900.0;
  const auto cols = decimate_min_max(x, y, lo, hi, columns);
  ASSERT_EQ(cols.size(), static_cast<size_t>(columns));
  std::vector<double> mn(columns, 1e300), mx(columns, -1e300);
  for (int i = 0; i < n; ++i) {
    const double xi = x[static_cast<size_t>(i)];
    if (xi < lo || xi > hi) continue;
    const int c = std::min(columns - 1, static_cast<int>((xi - lo) * columns / (hi - lo)));
    mn[static_cast<size_t>(c)] = std::min(mn[static_cast<size_t>(c)], y[static_cast<size_t>(i)]);
    mx[static_cast<size_t>(c)] = std::max(mx[static_cast<size_t>(c)], y[static_cast<size_t>(i)]);
  }
  for (int c = 0; c < columns; ++c) {
    ASSERT_TRUE(cols[static_cast<size_t>(c)].has_data) << c;
    EXPECT_FLOAT_EQ(cols[static_cast<size_t>(c)].y_min, static_cast<float>(mn[static_cast<size_t>(c)])) << c;
    EXPECT_FLOAT_EQ(cols[static_cast<size_t>(c)].y_max, static_cast<float>(mx[static_cast<size_t>(c)])) << c;
    if (c > 0) {
      EXPECT_TRUE(cols[static_cast<size_t>(c)].joins_previous) << c;
    }
  }
  // The spike at sample 4321 (x = 43.21) lies outside [100, 900]: not shown; inside, it would be.
  const auto all = decimate_min_max(x, y, 0, 1000, columns);
  float top = -1e30f;
  for (const auto& c : all) top = std::max(top, c.y_max);
  EXPECT_GT(top, 450.0f);
}

TEST(MinMaxDecimation, MissingValuesAreGapsNeverBridgedAndNeverZero) {
  //            col 0        col 1          col 2       col 3
  const std::vector<double> x = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5};
  const std::vector<double> y = {1.0, 2.0, 5.0, kPlotNaN, kPlotNaN, kPlotNaN, 7.0, 8.0};
  const auto cols = decimate_min_max(x, y, 0.0, 4.0, 4);
  ASSERT_EQ(cols.size(), 4u);
  EXPECT_TRUE(cols[0].has_data);
  EXPECT_FALSE(cols[0].touches_gap);
  EXPECT_TRUE(cols[1].has_data) << "a column with data and NaN keeps its data";
  EXPECT_TRUE(cols[1].touches_gap);
  EXPECT_FLOAT_EQ(cols[1].y_min, 5.0f);
  EXPECT_TRUE(cols[1].joins_previous);
  EXPECT_FALSE(cols[2].has_data) << "all NaN: a gap, not a zero";
  EXPECT_TRUE(cols[2].touches_gap);
  EXPECT_TRUE(cols[3].has_data);
  EXPECT_FALSE(cols[3].joins_previous) << "NaN between column 1 and 3: the line breaks";
  EXPECT_FLOAT_EQ(cols[3].y_first, 7.0f);
  EXPECT_FLOAT_EQ(cols[3].y_last, 8.0f);
}

TEST(MinMaxDecimation, TheSampleOnTheRightEdgeIsDrawn) {
  const std::vector<double> x = {0, 1, 2, 3, 4}, y = {5, 4, 3, 2, 1};
  const auto cols = decimate_min_max(x, y, 0.0, 4.0, 4);
  EXPECT_FLOAT_EQ(cols[3].y_last, 1.0f) << "x = 4, the view's right edge, belongs to the last column";
}

TEST(MinMaxDecimation, DegenerateInputsGiveEmptyColumns) {
  const std::vector<double> x = {0, 1}, y = {1, 2};
  EXPECT_TRUE(decimate_min_max(x, y, 1.0, 1.0, 10)[0].has_data == false);
  EXPECT_TRUE(decimate_min_max(x, y, 0.0, 1.0, 0).empty());
  const std::vector<double> short_y = {1};
  for (const auto& c : decimate_min_max(x, short_y, 0.0, 2.0, 4)) {
    EXPECT_FALSE(c.has_data);
  }
}

TEST(LinkedXRange, ZoomPanAndResetMoveEveryPlotTogetherInsideTheExtent) {
  LinkedXRange r;
  r.set_extent(0, 100);
  EXPECT_EQ(r.lo(), 0);
  EXPECT_EQ(r.hi(), 100);
  r.zoom(25, 0.5);  // about x = 25: it stays a quarter of the way across
  EXPECT_DOUBLE_EQ(r.lo(), 12.5);
  EXPECT_DOUBLE_EQ(r.hi(), 62.5);
  r.pan(-50);  // clamped at the left end
  EXPECT_DOUBLE_EQ(r.lo(), 0);
  EXPECT_DOUBLE_EQ(r.hi(), 50);
  r.zoom(50, 10);  // never wider than the data
  EXPECT_DOUBLE_EQ(r.lo(), 0);
  EXPECT_DOUBLE_EQ(r.hi(), 100);
  r.set_min_width(2);
  for (int i = 0; i < 40; ++i) r.zoom(70, 0.5);
  EXPECT_NEAR(r.hi() - r.lo(), 2.0, 1e-9);
  EXPECT_LE(r.lo(), 70);
  EXPECT_GE(r.hi(), 70);
  r.cursor = 71.0;
  r.reset();
  EXPECT_EQ(r.lo(), 0);
  EXPECT_EQ(r.hi(), 100);
  EXPECT_EQ(r.cursor, 71.0) << "the shared cursor survives a reset";
  r.set_extent(0, 200);  // more data arrived while everything was shown: still everything
  EXPECT_EQ(r.hi(), 200);
  r.zoom(50, 0.5);
  const double lo = r.lo(), hi = r.hi();
  r.set_extent(0, 300);  // more data while zoomed in: the view keeps its place
  EXPECT_EQ(r.lo(), lo);
  EXPECT_EQ(r.hi(), hi);
}

TEST(AxisTicks, RoundStepsAcrossTheRangeAndAFittedYRange) {
  EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(nice_ticks(-3.2, 7.9, 5), (std::vector<double>{-2, 0, 2, 4, 6}));
  const auto t = nice_ticks(0.013, 0.049, 4);
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(t.front(), 0.02, 1e-12);
  EXPECT_TRUE(nice_ticks(1, 1, 5).empty());
  const std::vector<double> x = {0, 1, 2, 3, 4}, y = {10, kPlotNaN, 30, 100, 20};
  const std::vector<std::span<const double>> xs = {x}, ys = {y};
  const auto [lo, hi] = fit_y_range(xs, ys, 0, 2, 0.0);  // only what is visible: 10 and 30
  EXPECT_DOUBLE_EQ(lo, 10);
  EXPECT_DOUBLE_EQ(hi, 30);
  const auto [flo, fhi] = fit_y_range(xs, ys, 4, 4, 0.0);
  EXPECT_DOUBLE_EQ(flo, 19);
  EXPECT_DOUBLE_EQ(fhi, 21);
}

}  // namespace plot_model_test
}  // namespace lmc::ui
