#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/layout/layout.h"
#include "tests/support/build_paths.h"
#include "tests/support/scratch_dir.h"

namespace lmc {
namespace {

std::filesystem::path asset(const std::string& rel) {
  return lmc::test::test_assets_dir() / rel;
}

TEST(DevicePose, RotationIsRzRyRxAppliedXFirst) {
  DevicePose p;
  p.rx_deg = 90;  // device +y (viewing axis) tips towards world +z
  EXPECT_TRUE(p.rotation().isApprox((Eigen::Matrix3d() << 1, 0, 0, 0, 0, -1, 0, 1, 0).finished(), 1e-12));
  DevicePose q;
  q.rx_deg = 90;
  q.rz_deg = 90;
  // x first: y → z (by Rx), then z stays z under Rz.
  EXPECT_TRUE(q.to_world({0, 1, 0}).isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  // x applied first, so the device x axis goes through Rx unchanged, then Rz turns it to +y.
  EXPECT_TRUE(q.to_world({1, 0, 0}).isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
}

TEST(DevicePose, DeviceToWorldAddsTranslationAfterRotation) {
  DevicePose p{10, 20, 30, 0, 90, 0};
  // Ry(90°) maps x → −z.
  EXPECT_TRUE(p.to_world({1, 0, 0}).isApprox(Eigen::Vector3d(10, 20, 29), 1e-12));
  EXPECT_TRUE(p.forward().isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
}

TEST(LayoutDevice, OffsetIsAppliedAfterThePose) {
  LayoutDevice d;
  d.pose = DevicePose{100, 0, 0, 0, 0, 90};
  d.offset_mm = {1, 2, 3};
  EXPECT_TRUE(d.to_world({10, 0, 0}).isApprox(Eigen::Vector3d(101, 12, 3), 1e-12));
}

TEST(LayoutJson, PaperLayoutsLoadWithTheirPublishedPoses) {
  const Layout init = load_layout(asset("layouts/paper-initial.json"));
  ASSERT_EQ(init.device_count(), 4);
  EXPECT_EQ(init.devices[3].slot, "LMC4");
  EXPECT_DOUBLE_EQ(init.devices[3].pose.x_mm, 60);
  EXPECT_DOUBLE_EQ(init.devices[3].pose.z_mm, -60);
  EXPECT_DOUBLE_EQ(init.devices[1].offset_mm.y(), 18.79);
  const Layout opt = load_layout(asset("layouts/paper-optimized.json"));
  EXPECT_DOUBLE_EQ(opt.devices[0].pose.z_mm, 256.29);
  EXPECT_DOUBLE_EQ(opt.devices[0].pose.rx_deg, 29.90);
  EXPECT_DOUBLE_EQ(opt.devices[1].offset_mm.z(), -82.96);
  const Layout processed = load_layout(asset("layouts/paper-optimized-as-processed.json"));
  EXPECT_DOUBLE_EQ(processed.devices[0].pose.z_mm, -256.29);
  EXPECT_EQ(processed.devices[1], opt.devices[1]);
}

TEST(LayoutJson, RoundTripsExactly) {
  Layout l = load_layout(asset("layouts/paper-optimized.json"));
  l.devices[2].serial = "LP55123";
  const auto dir = lmc::test::scratch_dir("layout_roundtrip");
  save_layout(l, dir / "l.json");
  EXPECT_EQ(load_layout(dir / "l.json"), l);
}

void expect_rejected(const nlohmann::json& j, const std::string& path_fragment) {
  try {
    layout_from_json(j, "bad.json");
    FAIL() << "accepted: " << j.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "bad.json");
    EXPECT_NE(e.where().json_path.find(path_fragment), std::string::npos)
        << "message: " << e.what() << " (wanted path containing " << path_fragment << ")";
  }
}

nlohmann::json good_layout() {
  return nlohmann::json::parse(R"({"format": 1, "name": "t", "devices": [
      {"slot": "LMC1", "pose": {"x": 0, "z": 0, "rx": 0, "ry": 0}, "offset": [0, 0, 0]},
      {"slot": "LMC2", "serial": "A1", "pose": {"x": 1, "y": 0, "z": 0, "rx": 0, "ry": 0, "rz": 0}}]})");
}

TEST(LayoutJson, RejectsBadFilesNamingTheJsonPath) {
  EXPECT_NO_THROW(layout_from_json(good_layout(), "ok.json"));
  auto j = good_layout();
  j["devices"][1]["slot"] = "LMC1";
  expect_rejected(j, "/devices/1/slot");
  j = good_layout();
  j["devices"][0]["serial"] = "A1";
  j["devices"][1]["serial"] = "A1";
  expect_rejected(j, "/devices/1/serial");
  j = good_layout();
  j["devices"][1]["pose"]["rx"] = "ten";
  expect_rejected(j, "/devices/1/pose/rx");
  j = good_layout();
  j["devices"][0]["offset"] = {1, 2};
  expect_rejected(j, "/devices/0/offset");
  j = good_layout();
  j["format"] = 7;
  expect_rejected(j, "/format");
  j = good_layout();
  j.erase("devices");
  expect_rejected(j, "/devices");
  j = good_layout();
  j["devices"] = nlohmann::json::array();
  expect_rejected(j, "/devices");
  j = good_layout();
  j["sensor"] = {{"range_mm", -5}};
  expect_rejected(j, "/sensor/range_mm");
  j = good_layout();
  j["devices"][0]["slot"] = "../../etc";
  expect_rejected(j, "/devices/0/slot");
  // A misspelt or unknown key is named, never dropped while a default takes its place.
  j = good_layout();
  j["sensor"] = {{"range", 400}};
  expect_rejected(j, "/sensor/range");
  j = good_layout();
  j["devices"][1]["pose"]["rq"] = 5;
  expect_rejected(j, "/devices/1/pose/rq");
  j = good_layout();
  j["devices"][0]["offest"] = {1, 2, 3};
  expect_rejected(j, "/devices/0/offest");
  j = good_layout();
  j["colour"] = "red";
  expect_rejected(j, "/colour");
  // x, z, rx, ry are required; null is not 0; y and rz may be left out (flat on the table).
  j = good_layout();
  j["devices"][1]["pose"].erase("z");
  expect_rejected(j, "/devices/1/pose/z");
  j = good_layout();
  j["devices"][1]["pose"]["x"] = nullptr;
  expect_rejected(j, "/devices/1/pose/x");
  j = good_layout();
  j["devices"][1]["pose"].erase("y");
  j["devices"][1]["pose"].erase("rz");
  EXPECT_EQ(layout_from_json(j, "flat.json").devices[1].pose.y_mm, 0.0);
}

TEST(LayoutValidation, RejectsNaNPoses) {
  Layout l = load_layout(asset("layouts/paper-initial.json"));
  l.devices[2].pose.ry_deg = std::nan("");
  EXPECT_EQ(validate_layout(l), "/devices/2/pose/ry: not a finite number");
}

TEST(LayoutJson, MalformedJsonNamesTheFile) {
  const auto p = lmc::test::scratch_dir("bad_layout") / "lmc_bad_layout.json";
  std::ofstream(p) << "{ \"format\": 1, ";
  try {
    load_layout(p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lmc_bad_layout.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos);
  }
}

}  // namespace
}  // namespace lmc
