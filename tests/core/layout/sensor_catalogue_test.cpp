#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/layout/layout.h"
#include "core/layout/sensor_catalogue.h"
#include "tests/support/build_paths.h"
#include "tests/support/scratch_dir.h"

namespace lmc {
namespace {

const SensorCatalogue& shipped() {
  static const SensorCatalogue c = load_sensor_catalogue(lmc::test::test_assets_dir() / "sensors" / "sensors.json");
  return c;
}

TEST(SensorCatalogue, ShippedCatalogueHoldsTheFourModels) {
  const SensorCatalogue& c = shipped();
  EXPECT_EQ(c.known_ids(), "study, lmc, lmc2, ir170");
  // The study's entry is exactly today's default sensor: the reference mode and parity tests use it.
  EXPECT_EQ(c.at("study", "test").sensor, SensorModel{});
  const SensorSpec& lmc2 = c.at("lmc2", "test");
  EXPECT_EQ(lmc2.name, "Leap Motion Controller 2");
  EXPECT_EQ(lmc2.sensor.fov_long_deg, 160.0);
  EXPECT_EQ(lmc2.sensor.range_mm, 1100.0);
  EXPECT_EQ(lmc2.sensor.range_near_mm, 100.0);
  EXPECT_EQ(lmc2.footprint_mm, Eigen::Vector3d(84, 20, 12));
  EXPECT_EQ(c.at("lmc", "test").sensor.fov_long_deg, 140.0);
  // Product ids name the hardware, never the study's model of it.
  ASSERT_NE(c.for_product_id(0x1206), nullptr);
  EXPECT_EQ(c.for_product_id(0x1206)->id, "lmc2");
  ASSERT_NE(c.for_product_id(0x0003), nullptr);
  EXPECT_EQ(c.for_product_id(0x0003)->id, "lmc");
  EXPECT_EQ(c.for_product_id(0x1203)->id, "ir170");
  EXPECT_EQ(c.for_product_id(0x9999), nullptr);
  // Position noise where the literature gives it: the middle of each controller's repeatability range.
  EXPECT_EQ(c.at("lmc", "test").position_noise_sd_mm.value_or(-1), 1.75);
  EXPECT_EQ(lmc2.position_noise_sd_mm.value_or(-1), 0.6);
  EXPECT_FALSE(c.at("study", "test").position_noise_sd_mm.has_value());
  EXPECT_FALSE(c.at("ir170", "test").position_noise_sd_mm.has_value());
}

TEST(SensorCatalogue, UnknownModelIsRefusedNamingTheKnownOnes) {
  try {
    shipped().at("lmc3", "rig.json, device \"LMC3\"");
    FAIL();
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rig.json, device \"LMC3\""), std::string::npos) << what;
    EXPECT_NE(what.find("\"lmc3\""), std::string::npos) << what;
    EXPECT_NE(what.find("study, lmc, lmc2, ir170"), std::string::npos) << what;
  }
}

nlohmann::json one_model() {
  return nlohmann::json::parse(R"({"format": 1, "models": [{
    "id": "study", "name": "s", "fov_long_deg": 150, "fov_short_deg": 120, "range_near_mm": 0,
    "range_far_mm": 600, "axis_cut_mm": 250, "frame_rate_hz": 120, "footprint_mm": [80, 30, 11.3],
    "origin_in_case_mm": [0, 11.3, 0], "leapc_product_ids": [3],
    "sources": {"fov": "a", "range": "b", "axis_cut": "c", "frame_rate": "d", "footprint": "e", "origin": "f",
                "product_ids": "g"}}]})");
}

void expect_catalogue_rejected(const nlohmann::json& j, const std::string& path) {
  try {
    sensor_catalogue_from_json(j, "sensors.json");
    FAIL() << "accepted: " << j.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "sensors.json");
    EXPECT_EQ(e.where().json_path, path) << e.what();
  }
}

TEST(SensorCatalogue, BadFilesAreRefusedNamingFileAndField) {
  EXPECT_NO_THROW(sensor_catalogue_from_json(one_model(), "ok.json"));
  auto j = one_model();
  j["models"][0]["sources"].erase("fov");
  expect_catalogue_rejected(j, "/models/0/sources/fov");
  j = one_model();
  j["models"][0]["sources"]["range"] = "";
  expect_catalogue_rejected(j, "/models/0/sources/range");
  j = one_model();
  j["models"][0]["fov_long_deg"] = 190;
  expect_catalogue_rejected(j, "/models/0/fov_long_deg");
  j = one_model();
  j["models"][0]["range_far_mm"] = -1;
  expect_catalogue_rejected(j, "/models/0/range_far_mm");
  j = one_model();
  j["models"][0]["range_near_mm"] = 700;
  expect_catalogue_rejected(j, "/models/0/range_near_mm");
  j = one_model();
  j["models"][0]["footprint_mm"] = {80, 30};
  expect_catalogue_rejected(j, "/models/0/footprint_mm");
  j = one_model();
  j["models"].push_back(j["models"][0]);
  expect_catalogue_rejected(j, "/models/1/id");
  j = one_model();
  j["models"][0]["id"] = "lmc";
  expect_catalogue_rejected(j, "/models");  // no study entry
  j = one_model();
  j["models"][0]["colour"] = "grey";
  expect_catalogue_rejected(j, "/models/0/colour");
}

TEST(SensorCatalogue, PositionNoiseIsOptionalAndNeedsItsSource) {
  EXPECT_FALSE(sensor_catalogue_from_json(one_model(), "ok.json").models[0].position_noise_sd_mm.has_value());
  auto j = one_model();
  j["models"][0]["position_noise_sd_mm"] = 1.3;
  j["models"][0]["sources"]["position_noise"] = "h";
  EXPECT_EQ(sensor_catalogue_from_json(j, "ok.json").models[0].position_noise_sd_mm.value_or(-1), 1.3);
  j["models"][0]["position_noise_sd_mm"] = 0;  // a model that does not scatter at all is allowed
  EXPECT_EQ(sensor_catalogue_from_json(j, "ok.json").models[0].position_noise_sd_mm.value_or(-1), 0.0);
  j["models"][0]["sources"].erase("position_noise");
  expect_catalogue_rejected(j, "/models/0/sources/position_noise");  // a figure without its source
  j = one_model();
  j["models"][0]["sources"]["position_noise"] = "h";
  expect_catalogue_rejected(j, "/models/0/sources/position_noise");  // a source without its figure
}

TEST(SensorCatalogue, ABadPositionNoiseIsRefusedNamingFileModelAndField) {
  for (const nlohmann::json& bad : {nlohmann::json(-0.5), nlohmann::json("1.3 mm"), nlohmann::json(nullptr)}) {
    auto j = one_model();
    j["models"][0]["position_noise_sd_mm"] = bad;
    j["models"][0]["sources"]["position_noise"] = "h";
    try {
      sensor_catalogue_from_json(j, "sensors.json");
      FAIL() << "accepted " << bad.dump();
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                "sensors.json: at /models/0/position_noise_sd_mm: model \"study\": "
                "position_noise_sd_mm must be a number ≥ 0 (mm), not " +
                    bad.dump());
    }
  }
}

nlohmann::json v2_layout() {
  return nlohmann::json::parse(R"({"format": 2, "name": "mixed", "devices": [
      {"slot": "LMC1", "model": "lmc2", "pose": {"x": 0, "z": 0, "rx": 0, "ry": 0}},
      {"slot": "LMC2", "model": "lmc", "overrides": {"range_mm": 400}, "pose": {"x": 100, "z": 0, "rx": 0, "ry": 0}},
      {"slot": "LMC3", "model": "study", "pose": {"x": 0, "z": 100, "rx": 0, "ry": 0}}]})");
}

TEST(LayoutJsonV2, EachDeviceNamesItsModelWithOptionalOverrides) {
  const Layout l = layout_from_json(v2_layout(), "mixed.json", shipped());
  EXPECT_EQ(l.devices[0].model, "lmc2");
  EXPECT_EQ(l.devices[0].sensor, shipped().at("lmc2", "").sensor);
  EXPECT_EQ(l.devices[0].footprint_mm, Eigen::Vector2d(84, 20));  // the LMC2's case on the table
  EXPECT_EQ(l.devices[2].footprint_mm, Eigen::Vector2d(80, 30));
  EXPECT_EQ(l.devices[1].model, "lmc");
  EXPECT_EQ(l.devices[1].sensor.range_mm, 400.0);
  EXPECT_EQ(l.devices[1].sensor.fov_long_deg, 140.0);
  EXPECT_EQ(l.devices[2].sensor, SensorModel{});
  EXPECT_FALSE(uniform_sensors(l));
  EXPECT_THROW(common_sensor(l), Error);
  // Written back: the model, and only the fields that differ from it.
  const nlohmann::json out = layout_to_json(l, shipped());
  EXPECT_EQ(out["format"], 2);
  EXPECT_FALSE(out.contains("sensor"));
  EXPECT_EQ(out["devices"][1]["model"], "lmc");
  EXPECT_EQ(out["devices"][1]["overrides"], nlohmann::json({{"range_mm", 400.0}}));
  EXPECT_FALSE(out["devices"][0].contains("overrides"));
  EXPECT_EQ(layout_from_json(out, "again.json", shipped()), l);
}

TEST(LayoutJsonV2, UnknownModelIsRefusedNamingFileDeviceAndKnownModels) {
  auto j = v2_layout();
  j["devices"][1]["model"] = "lmc3";
  try {
    layout_from_json(j, "mixed.json", shipped());
    FAIL();
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.where().file, "mixed.json");
    EXPECT_EQ(e.where().json_path, "/devices/1/model");
    EXPECT_NE(what.find("\"LMC2\""), std::string::npos) << what;
    EXPECT_NE(what.find("\"lmc3\""), std::string::npos) << what;
    EXPECT_NE(what.find("study, lmc, lmc2, ir170"), std::string::npos) << what;
  }
  j = v2_layout();
  j["devices"][0].erase("model");
  EXPECT_THROW(layout_from_json(j, "mixed.json", shipped()), Error);
  j = v2_layout();
  j["devices"][1]["overrides"] = {{"fov_long_deg", 200}};
  try {
    layout_from_json(j, "mixed.json", shipped());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().json_path, "/devices/1/overrides/fov_long_deg") << e.what();
  }
  j = v2_layout();
  j["sensor"] = {{"range_mm", 400}};  // version 2 has no global sensor
  EXPECT_THROW(layout_from_json(j, "mixed.json", shipped()), Error);
}

TEST(LayoutJsonV1, GlobalSensorAppliesToEveryDeviceAndIsWrittenBackAsV2) {
  const Layout paper = load_layout(lmc::test::test_assets_dir() / "layouts" / "paper-optimized.json");
  for (const auto& d : paper.devices) {
    EXPECT_EQ(d.model, "study");
    EXPECT_EQ(d.sensor, SensorModel{});
  }
  // A version-1 file with other values: every device gets them, as overrides of the study's model.
  auto j = nlohmann::json::parse(R"({"format": 1, "name": "t", "sensor": {"range_mm": 400},
      "devices": [{"slot": "A", "pose": {"x": 0, "z": 0, "rx": 0, "ry": 0}},
                  {"slot": "B", "pose": {"x": 100, "z": 0, "rx": 0, "ry": 0}}]})");
  const Layout l = layout_from_json(j, "v1.json", shipped());
  for (const auto& d : l.devices) {
    EXPECT_EQ(d.model, "study");
    EXPECT_EQ(d.sensor.range_mm, 400.0);
    EXPECT_EQ(d.sensor.fov_long_deg, 150.0);
  }
  const auto dir = lmc::test::scratch_dir("layout_v1_to_v2");
  save_layout(l, dir / "l.json");
  const Layout again = load_layout(dir / "l.json");
  EXPECT_EQ(again, l);
  EXPECT_EQ(layout_to_json(again, shipped())["devices"][0]["overrides"], nlohmann::json({{"range_mm", 400.0}}));
}

TEST(LayoutModels, ModelListSetsEachSlotOrAll) {
  Layout l = square_layout("sq");
  set_models_from_list(l, "lmc2,lmc2,lmc,lmc", shipped());
  EXPECT_EQ(l.devices[0].model, "lmc2");
  EXPECT_EQ(l.devices[3].model, "lmc");
  EXPECT_EQ(l.devices[3].sensor, shipped().at("lmc", "").sensor);
  set_models_from_list(l, "ir170", shipped());
  for (const auto& d : l.devices) EXPECT_EQ(d.model, "ir170");
  EXPECT_THROW(set_models_from_list(l, "lmc2,lmc", shipped()), Error);
  EXPECT_THROW(set_models_from_list(l, "lmc2,lmc2,lmc,lmcX", shipped()), Error);
}

}  // namespace
}  // namespace lmc
