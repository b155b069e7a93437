// The Review figures as core figures: a Bland–Altman plot groups points by subject
// and draws the bias and both limits at the table's values; a trial's figure is eleven panels of
// fused LMC against Vicon with NaN kept; the visibility map places motions in order; file stems
// are safe names.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/safe_name.h"
#include "core/review/review_figures.h"

namespace lmc {
namespace review_figures_test {  // named: test files share unity batches

TEST(ReviewFigures, BlandAltmanPointsBySubjectWithTheTablesLines) {
  AgreementGroup g;
  g.layout = "initial";
  g.pose = "horizontal";
  MeasureAgreement m;
  m.measure.part = "index";
  m.measure.quantity = "finger length";
  m.measure.unit = "mm";
  m.points = {{70, -2, "S01", "a"}, {71, -3, "S02", "b"}, {72, -1, "S01", "c"}};
  m.n_trials = 3;
  m.n_subjects = 2;
  m.bland_altman.bias = -2;
  m.bland_altman.loa_low = -4;
  m.bland_altman.loa_high = 0;
  m.bland_altman.method = "repeated measures";
  const Figure f = bland_altman_figure(g, m);
  ASSERT_EQ(f.series.size(), 2u);
  EXPECT_EQ(f.series[0].name, "S01");
  EXPECT_EQ(f.series[0].x, (std::vector<double>{70, 72}));
  EXPECT_EQ(f.series[0].y, (std::vector<double>{-2, -1}));
  EXPECT_EQ(f.series[0].style, SeriesStyle::points);
  ASSERT_EQ(f.references.size(), 3u);
  EXPECT_DOUBLE_EQ(f.references[0].y, -2);
  EXPECT_EQ(f.references[0].label, "bias -2.0 mm");
  EXPECT_DOUBLE_EQ(f.references[1].y, -4);
  EXPECT_DOUBLE_EQ(f.references[2].y, 0);
  EXPECT_EQ(f.y.unit, "mm");
  EXPECT_NE(f.notes.at(0).find("repeated measures"), std::string::npos);
  // No limits (one subject): no lines, and the note says why.
  m.bland_altman = {};
  m.bland_altman.reason = "needs two subjects";
  const Figure none = bland_altman_figure(g, m);
  EXPECT_TRUE(none.references.empty());
  EXPECT_EQ(none.notes.back(), "No limits: needs two subjects");
}

TEST(ReviewFigures, BlandAltmanLabelsNeverShowANegativeZero) {
  AgreementGroup g;
  g.layout = "all";
  g.pose = "all";
  MeasureAgreement m;
  m.measure.unit = "mm";
  m.bland_altman.bias = 0.3;
  m.bland_altman.loa_low = -0.04;  // rounds to zero at one decimal
  m.bland_altman.loa_high = 0.64;
  const Figure f = bland_altman_figure(g, m);
  ASSERT_EQ(f.references.size(), 3u);
  EXPECT_EQ(f.references[0].label, "bias +0.3 mm");
  EXPECT_EQ(f.references[1].label, "lower 0.0 mm");
  EXPECT_EQ(f.references[2].label, "upper +0.6 mm");
}

TEST(ReviewFigures, ATrialIsElevenPanelsOfFusedAgainstViconWithGapsKept) {
  TrialSeries s;
  s.trial = "Naiv_Index101";
  s.time_s = {0, 0.01, 0.02};
  s.has_vicon = true;
  for (auto& v : s.fused.angle_deg) v = {1, std::nan(""), 3};
  for (auto& v : s.fused.finger_mm) v = {70, 71, 72};
  for (auto& v : s.vicon.angle_deg) v = {1.5, 2.5, 3.5};
  for (auto& v : s.vicon.finger_mm) v = {75, 75, 75};
  DeviceSeries d;
  d.device_id = 3;
  d.measures = s.fused;
  s.devices.push_back(d);
  const FigureGrid g = trial_figure(s);
  ASSERT_EQ(g.panels.size(), 11u);
  EXPECT_EQ(g.x.unit, "s");
  EXPECT_EQ(g.panels[0].y.label, "index_mcp");
  EXPECT_EQ(g.panels[10].y.label, "pinky length");
  ASSERT_EQ(g.panels[0].series.size(), 2u);
  EXPECT_EQ(g.panels[0].series[1].name, "Vicon");
  EXPECT_TRUE(std::isnan(g.panels[0].series[0].y[1]));  // a gap stays a gap
  EXPECT_EQ(trial_figure(s, true).panels[0].series.back().name, "LMC3");
}

TEST(ReviewFigures, TheVisibilityMapPlacesMotionsInOrder) {
  VisibilityMap map;
  map.cells = {{"LMC1", "static", "initial", 1, 5, 0, 0.8, 0.1},
               {"LMC1", "index", "initial", 1, 5, 0, 0.6, 0.1},
               {"LMC1", "static", "optimized", 1, 5, 0, 0.9, 0.1}};
  const Figure f = visibility_map_figure(map);
  ASSERT_EQ(f.series.size(), 2u);
  EXPECT_EQ(f.series[0].name, "LMC1 initial");
  EXPECT_EQ(f.series[0].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(f.series[1].x, (std::vector<double>{1}));
  EXPECT_EQ(f.notes.at(0), "motions: 1 static, 2 index");
}

TEST(ReviewFigures, StemsAreSafeFileNames) {
  EXPECT_EQ(figure_stem("bland-altman-initial-horizontal-rom_index_mcp"),
            "bland-altman-initial-horizontal-rom_index_mcp");
  EXPECT_EQ(figure_stem("../Trial A/B"), "trial-a-b");
  EXPECT_EQ(figure_stem("///"), "figure");
  EXPECT_NO_THROW(require_safe_name(figure_stem("../../etc/passwd"), "stem"));
}

}  // namespace review_figures_test
}  // namespace lmc
