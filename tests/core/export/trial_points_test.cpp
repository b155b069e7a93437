// The export's point table (core/export/trial_points.h) from a small hand-made processed trial:
// labels as documented, every value where processing left it, missing points NaN (never 0), Vicon
// frame f at grid frame f, OpenSim axes a rotation of the world's; and the table through our C3D
// and TRC writers and back through our readers to 1e-3 mm, with the C3D parameters in place.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/common/error.h"
#include "core/export/trial_points.h"
#include "core/hand/hand_frame.h"
#include "core/io/c3d.h"
#include "core/io/trc.h"

namespace lmc {
namespace trial_points_test {  // named: test files share unity batches

constexpr double kNaNv = std::numeric_limits<double>::quiet_NaN();

Vec3 value(int who, int f, int i) {
  return {100.0 * who + 0.125 * f + i, -50.0 + 0.5 * i - f, 300.25 + who - 0.001 * i};
}

// Five frames; the fused hand is missing in frame 2, LMC2 has no hand in frames 0–1, Vicon has two
// markers (one with a character a label cannot hold, one with a gap) and only four frames.
TrialAnalysis small_trial() {
  TrialAnalysis r;
  r.tag.trial = "Naiv_Index101";
  r.world.frame_count = 5;
  r.world.step_us = 10000.0;
  r.fused = HandTrack(5);
  for (int id : {1, 2}) r.world.devices.push_back({id, HandTrack(5)});
  for (int f = 0; f < 5; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      if (f != 2) r.fused.at(f, i) = value(0, f, i);
      r.world.devices[0].track.at(f, i) = value(1, f, i);
      if (f >= 2) r.world.devices[1].track.at(f, i) = value(2, f, i);
    }
  }
  r.has_vicon = true;
  return r;
}

MarkerSeries small_markers() {
  MarkerSeries m;
  m.names = {"Subj:RWRA", "RFIN"};
  for (int f = 0; f < 4; ++f) {
    m.positions.push_back({Vec3(10.0 + f, 20.0, 30.0), f == 1 ? Vec3::Constant(kNaNv) : Vec3(-5.0, 7.5 * f, 1.0)});
  }
  return m;
}

bool missing(const Eigen::Vector3d& p) {
  return p.array().isNaN().any();
}

TEST(ExportPoints, LabelsValuesAndMissingPointsAsDocumented) {
  const TrialAnalysis r = small_trial();
  const MarkerSeries m = small_markers();
  const PointTable t = trial_point_table(r, &m, ExportAxes::kWorld);
  ASSERT_EQ(t.frame_count(), 5);
  ASSERT_EQ(t.point_count(), 3 * 28 + 2);
  EXPECT_EQ(t.labels[0], "F_Palm");
  EXPECT_EQ(t.labels[1], "F_Elbow");
  EXPECT_EQ(t.labels[2], "F_Wrist");
  EXPECT_EQ(t.labels[3], "F_Thumb_Meta");
  EXPECT_EQ(t.labels[27], "F_Pinky_End");
  EXPECT_EQ(t.labels[28], "LMC1_Palm");
  EXPECT_EQ(t.labels[84], "V_Subj_RWRA");
  EXPECT_EQ(t.labels[85], "V_RFIN");
  EXPECT_EQ(t.descriptions[t.label_index("F_Index_Dist")], "fused hand: index finger last joint (Finger2_Dist)");
  EXPECT_EQ(t.descriptions[84], "Vicon marker Subj:RWRA");
  EXPECT_TRUE(t.has_vicon);
  EXPECT_DOUBLE_EQ(t.rate_hz, 100.0);

  const int fused_index_dist = t.label_index("F_Index_Dist");
  const int lmc2_index_dist = t.label_index("LMC2_Index_Dist");
  ASSERT_GE(fused_index_dist, 0);
  ASSERT_GE(lmc2_index_dist, 0);
  const int idx = digit_point(Digit::kIndex, Joint::kDist);
  EXPECT_EQ(t.positions[0][static_cast<size_t>(fused_index_dist)], value(0, 0, idx));
  EXPECT_EQ(t.positions[4][static_cast<size_t>(lmc2_index_dist)], value(2, 4, idx));
  EXPECT_TRUE(missing(t.positions[2][static_cast<size_t>(fused_index_dist)]));  // no fused hand
  EXPECT_TRUE(missing(t.positions[1][static_cast<size_t>(lmc2_index_dist)]));   // LMC2 saw nothing yet
  EXPECT_EQ(t.positions[3][84], Vec3(13.0, 20.0, 30.0));                        // Vicon frame 3 = grid frame 3
  EXPECT_TRUE(missing(t.positions[1][85]));                                     // Vicon gap
  EXPECT_TRUE(missing(t.positions[4][84]));                                     // past the Vicon file's end

  // No Vicon: the hands only.
  const PointTable no_vicon = trial_point_table(r, nullptr, ExportAxes::kWorld);
  EXPECT_EQ(no_vicon.point_count(), 3 * 28);
  EXPECT_FALSE(no_vicon.has_vicon);
}

TEST(ExportPoints, OpenSimAxesRotateTheWorldFrame) {
  const TrialAnalysis r = small_trial();
  const PointTable w = trial_point_table(r, nullptr, ExportAxes::kWorld);
  const PointTable o = trial_point_table(r, nullptr, ExportAxes::kOpenSim);
  const Vec3 p = w.positions[0][0], q = o.positions[0][0];
  EXPECT_EQ(q, Vec3(-p.z(), p.y(), p.x()));
  EXPECT_DOUBLE_EQ(q.norm(), p.norm());
  EXPECT_EQ(export_axes_from_name("opensim"), ExportAxes::kOpenSim);
  EXPECT_THROW(export_axes_from_name("zup"), Error);
}

void expect_same_points(const PointTable& t, const std::vector<std::vector<Eigen::Vector3d>>& back, const char* what) {
  ASSERT_EQ(back.size(), t.positions.size()) << what;
  int missing_points = 0;
  for (size_t f = 0; f < back.size(); ++f) {
    ASSERT_EQ(back[f].size(), t.positions[f].size()) << what;
    for (size_t p = 0; p < back[f].size(); ++p) {
      if (missing(t.positions[f][p])) {
        EXPECT_TRUE(missing(back[f][p])) << what << " frame " << f << " " << t.labels[p];
        ++missing_points;
        continue;
      }
      EXPECT_LT((back[f][p] - t.positions[f][p]).cwiseAbs().maxCoeff(), 1e-3)
          << what << " frame " << f << " " << t.labels[p];
    }
  }
  EXPECT_GT(missing_points, 28) << what;
}

TEST(ExportPoints, C3dAndTrcReadBackToAThousandthOfAMillimetre) {
  const TrialAnalysis r = small_trial();
  const MarkerSeries m = small_markers();
  const PointTable t = trial_point_table(r, &m, ExportAxes::kWorld);

  const C3dData c = parse_c3d(write_c3d_bytes(point_table_c3d(t)), "export.c3d");
  EXPECT_EQ(c.labels, t.labels);
  EXPECT_EQ(c.descriptions, t.descriptions);
  EXPECT_LT(c.point_scale, 0.0);
  EXPECT_TRUE(c.float_storage);
  EXPECT_DOUBLE_EQ(c.point_rate_hz, 100.0);
  EXPECT_EQ(c.units, "mm");
  EXPECT_EQ(c.first_frame, 1);
  EXPECT_EQ(c.manufacturer_company, "lmc-workbench");
  EXPECT_EQ(c.manufacturer_version, LMC_VERSION);
  EXPECT_NE(c.manufacturer_software.find("y up"), std::string::npos) << c.manufacturer_software;
  for (const char* p :
       {"POINT:USED", "POINT:SCALE", "POINT:RATE", "POINT:FRAMES", "POINT:UNITS", "POINT:LABELS", "POINT:DESCRIPTIONS",
        "TRIAL:ACTUAL_START_FIELD", "TRIAL:ACTUAL_END_FIELD", "MANUFACTURER:VERSION_LABEL"}) {
    EXPECT_NE(std::find(c.parameter_names.begin(), c.parameter_names.end(), p), c.parameter_names.end()) << p;
  }
  expect_same_points(t, c.positions, "C3D");

  std::ostringstream trc_text;
  write_trc(trc_text, point_table_trc(t));
  EXPECT_EQ(trc_text.str().rfind("PathFileType\t4\t(X/Y/Z)", 0), 0u);
  const TrcData back = parse_trc_text(trc_text.str(), "export.trc");
  EXPECT_EQ(back.marker_names, t.labels);
  EXPECT_EQ(back.units, "mm");
  EXPECT_DOUBLE_EQ(back.data_rate_hz, 100.0);
  EXPECT_DOUBLE_EQ(back.times_s[3], 0.03);
  EXPECT_TRUE(back.warnings.empty());
  expect_same_points(t, back.positions, "TRC");
}

}  // namespace trial_points_test
}  // namespace lmc
