#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/vicon_mapping.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

MarkerSeries study_markers(int frames) {
  const ViconMapping m = load_vicon_mapping(test::asset_file("mappings/vicon-26-to-lmc.json"));
  MarkerSeries s;
  s.names = m.markers;
  s.source = "t.trc";
  for (int f = 0; f < frames; ++f) {
    std::vector<Eigen::Vector3d> row;
    for (size_t k = 0; k < s.names.size(); ++k) row.emplace_back(static_cast<double>(k), 10.0 * f, 1.0);
    s.positions.push_back(row);
  }
  return s;
}

TEST(ViconMapping, ShippedFileReproducesTheStudyMapping) {
  const ViconMapping m = load_vicon_mapping(test::asset_file("mappings/vicon-26-to-lmc.json"));
  ASSERT_EQ(m.markers.size(), 26u);
  const HandTrack t = apply_vicon_mapping(m, study_markers(2));
  // Marker k sits at x = k: palm = Hand4 (index 6), elbow = Forearm1 (0), wrist = mean(1, 2).
  EXPECT_DOUBLE_EQ(t.at(1, kPalm).x(), 6.0);
  EXPECT_DOUBLE_EQ(t.at(1, kElbow).x(), 0.0);
  EXPECT_DOUBLE_EQ(t.at(1, kWrist).x(), 1.5);
  EXPECT_DOUBLE_EQ(t.at(1, kWrist).y(), 10.0);
  // Middle Meta = Hand3 + 0.33 (Hand1 − Hand3) = 5 + 0.33·(3 − 5).
  EXPECT_NEAR(t.at(0, digit_point(2, 0)).x(), 5.0 - 0.66, 1e-12);
  EXPECT_DOUBLE_EQ(t.at(0, digit_point(0, 0)).x(), 4.0);  // thumb Meta = Proxi = Hand2
  EXPECT_DOUBLE_EQ(t.at(0, digit_point(0, 1)).x(), 4.0);
  EXPECT_DOUBLE_EQ(t.at(0, digit_point(4, 4)).x(), 25.0);  // pinky End = Pinky4_1
  EXPECT_EQ(t.at(0, kPalmNormal), Vec3::Zero());
}

TEST(ViconMapping, MissingMarkersAreClearErrors) {
  const ViconMapping m = load_vicon_mapping(test::asset_file("mappings/vicon-26-to-lmc.json"));
  MarkerSeries s = study_markers(3);
  s.names[12] = "Renamed";  // Index3_1 absent
  try {
    apply_vicon_mapping(m, s);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Index3_1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("t.trc"), std::string::npos) << e.what();
  }
  s = study_markers(3);
  for (auto& row : s.positions) row[20] = Eigen::Vector3d::Constant(kNaN);
  try {
    apply_vicon_mapping(m, s);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing in every frame"), std::string::npos) << e.what();
  }
  // A subject prefix is accepted.
  s = study_markers(1);
  for (auto& n : s.names) n = "Subj:" + n;
  EXPECT_DOUBLE_EQ(apply_vicon_mapping(m, s).at(0, kPalm).x(), 6.0);
}

TEST(ViconMapping, BadMappingFilesNameTheField) {
  const auto j = nlohmann::json::parse(R"({"format":1,"markers":["A"],"points":{"Palm Position":{"B":1.0}}})");
  try {
    vicon_mapping_from_json(j, "m.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/points/Palm Position/B"), std::string::npos) << e.what();
  }
  const auto k = nlohmann::json::parse(R"({"format":1,"markers":["A"],"points":{"Knuckle":{"A":1.0}}})");
  EXPECT_THROW(vicon_mapping_from_json(k, "m.json"), Error);
}

}  // namespace
}  // namespace lmc
