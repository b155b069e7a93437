// Headless tests of the Inspector's per-controller model: the Model combo, the sensor values with
// their override marks, "Reset to model", "Apply this model to all controllers", the undo names,
// and layout files with models (a version-1 file written back as version 2, a mixed rig round trip).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/paths.h"
#include "core/io/layout_json.h"
#include "core/io/sensor_catalogue_json.h"
#include "tests/support/scratch_dir.h"
#include "tests/ui/tabs/layout/inspector_fixture.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/tabs/layout/inspector_panel.h"

namespace lmc::ui {
namespace layout_inspector_models_test {

using testing::HeadlessImGui;

const SensorModel& model_sensor(const std::string& id) {
  return sensor_catalogue().at(id, "test").sensor;
}

// The Inspector at the width the Layout tab gives its right-hand panels (470 px less the frame).
struct ModelInspector : test::InspectorAt<460> {
  void pick_model(const std::string& id) {
    click("model");
    click("model." + id);
  }
  const LayoutDevice& head_device(int i) const {
    return state->history().head().layout.devices[static_cast<size_t>(i)];
  }
};

TEST_F(ModelInspector, PickingAModelChangesThatControllerOnly) {
  state->select(1);
  const Layout before = state->history().head().layout;
  pick_model("lmc2");
  EXPECT_EQ(head_device(1).model, "lmc2");
  EXPECT_EQ(head_device(1).sensor, model_sensor("lmc2"));
  EXPECT_DOUBLE_EQ(head_device(1).footprint_mm.x(), 84.0);
  for (int i : {0, 2, 3}) EXPECT_EQ(head_device(i), before.devices[static_cast<size_t>(i)]) << "controller " << i;
  EXPECT_EQ(state->history().undo_size(), 1u);
  EXPECT_EQ(state->history().undo_message(), "Model of LMC2: Leap Motion Controller 2");

  // The list names every controller's model; the combo shows the selected one's by name.
  const std::string text = gui.frame_text(body());
  EXPECT_NE(text.find("LMC1  study"), std::string::npos) << text;
  EXPECT_NE(text.find("LMC2  lmc2"), std::string::npos) << text;
  EXPECT_NE(text.find("Leap Motion Controller 2"), std::string::npos) << text;
  EXPECT_EQ(text.find("overrides"), std::string::npos) << "a model just picked overrides nothing: " << text;
}

TEST_F(ModelInspector, TheStudysModelIsNamedAsSuchInTheCombo) {
  state->select(0);
  click("model");
  const std::string text = gui.frame_text(body());
  EXPECT_NE(text.find("Leap Motion Controller, as the study modelled it"), std::string::npos) << text;
  for (const SensorSpec& m : sensor_catalogue().models) {
    EXPECT_TRUE(inspector.anchors().centre("model." + m.id).has_value()) << m.id << " in the open combo";
    EXPECT_NE(text.find(m.name), std::string::npos) << m.name;
  }
}

// The simulator's noise per model is shown beside the sensor values: the published figure where
// the catalogue has one, otherwise the simulator's own default, said as such.
TEST_F(ModelInspector, ShowsEachModelsPositionNoiseAndWhereItComesFrom) {
  state->select(1);
  pick_model("lmc2");
  std::string text = gui.frame_text(body());
  EXPECT_NE(text.find("Position noise 0.60\u00a0mm SD per axis (published)"), std::string::npos) << text;
  EXPECT_TRUE(inspector.anchors().centre("position-noise").has_value());
  pick_model("lmc");
  text = gui.frame_text(body());
  EXPECT_NE(text.find("Position noise 1.75\u00a0mm SD per axis (published)"), std::string::npos) << text;
  pick_model("study");
  text = gui.frame_text(body());
  EXPECT_NE(text.find("no published figure; the simulated rig uses 1\u00a0mm SD per axis"), std::string::npos) << text;
}

TEST_F(ModelInspector, DraggingARangeOverridesItMarkedAndResetToModelTakesItBack) {
  state->select(2);
  pick_model("lmc");
  gui.frame(body());
  EXPECT_FALSE(inspector.anchors().centre("override.range").has_value());
  const auto from = inspector.anchors().centre("sensor.range");
  ASSERT_TRUE(from.has_value());
  gui.drag(*from, ImVec2(from->x + 60, from->y), 6, body());
  EXPECT_GT(head_device(2).sensor.range_mm, 650.0) << "dragged right: a longer range than the LMC's 600 mm";
  EXPECT_EQ(head_device(2).model, "lmc") << "an override keeps the model";
  EXPECT_EQ(head_device(2).sensor.fov_long_deg, 140.0);
  EXPECT_EQ(state->history().undo_size(), 2u) << "the drag is one undo step";
  EXPECT_EQ(state->history().undo_message(), "Range of LMC3");
  EXPECT_EQ(head_device(1).sensor, model_sensor("study")) << "the other controllers keep theirs";

  const std::string text = gui.frame_text(body());
  EXPECT_NE(text.find("overrides 600 mm"), std::string::npos) << text;
  EXPECT_TRUE(inspector.anchors().fits_across("override.range")) << "the mark is whole";
  EXPECT_FALSE(inspector.anchors().centre("override.fov_long").has_value()) << "only the changed field is marked";

  click("reset-sensor");
  EXPECT_EQ(head_device(2).sensor, model_sensor("lmc"));
  EXPECT_EQ(state->history().undo_message(), "Reset LMC3 to its model");
  gui.frame(body());
  EXPECT_FALSE(inspector.anchors().centre("override.range").has_value());
}

TEST_F(ModelInspector, UndoAndRedoNameEachStep) {
  state->select(1);
  pick_model("lmc2");
  SensorModel s = head_device(1).sensor;
  s.fov_short_deg = 140;
  ASSERT_TRUE(set_device_sensor(state->upd_history(), 1, s));
  state->select(3);
  pick_model("ir170");

  const auto& h = state->history();
  EXPECT_EQ(h.undo_message(), "Model of LMC4: Stereo IR 170");
  state->undo();
  EXPECT_EQ(h.redo_message(), "Model of LMC4: Stereo IR 170");
  EXPECT_EQ(h.undo_message(), "Field of view of LMC2");
  EXPECT_EQ(head_device(3).model, "study");
  state->undo();
  EXPECT_EQ(h.undo_message(), "Model of LMC2: Leap Motion Controller 2");
  EXPECT_EQ(head_device(1).sensor, model_sensor("lmc2"));
  state->undo();
  EXPECT_EQ(head_device(1).model, "study");
  EXPECT_EQ(head_device(1).sensor, model_sensor("study"));
  state->redo();
  state->redo();
  EXPECT_DOUBLE_EQ(head_device(1).sensor.fov_short_deg, 140.0);
  state->redo();
  EXPECT_EQ(head_device(3).model, "ir170");
}

TEST_F(ModelInspector, ApplyThisModelToAllControllersIsOneStepAndEveryLabelFits) {
  state->select(0);
  pick_model("lmc2");
  gui.frame(body());
  for (const char* a : {"model", "sensor.fov_long", "sensor.axis_cut", "reset-sensor", "model-to-all"})
    EXPECT_TRUE(inspector.anchors().fits_across(a)) << a << " runs off the panel";
  click("model-to-all");
  EXPECT_EQ(state->history().undo_size(), 2u);
  EXPECT_EQ(state->history().undo_message(), "Model of every controller: Leap Motion Controller 2");
  for (int i = 0; i < 4; ++i) EXPECT_EQ(head_device(i).model, "lmc2") << i;
}

// ---- layout files with models ------------------------------------------------------------------

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(LayoutFileModels, AVersion1LayoutOpenedAndSavedIsWrittenAsVersion2WithModels) {
  const auto dir = test::scratch_dir("layout_v1_to_v2");
  // The shipped paper layout is a version-1 file; a copy with a 400 mm range too (an override).
  nlohmann::json v1 = read_json(assets_dir() / "layouts" / "paper-initial.json");
  ASSERT_EQ(v1.at("format"), 1);
  v1["sensor"]["range_mm"] = 400.0;
  std::ofstream(dir / "v1-400.json") << v1.dump(2);

  LayoutState plain(make_document(default_new_layout()));
  ASSERT_EQ(plain.open_file(assets_dir() / "layouts" / "paper-initial.json"), "");
  ASSERT_EQ(plain.save_to(dir / "plain.json"), "");
  const nlohmann::json plain_out = read_json(dir / "plain.json");
  EXPECT_EQ(plain_out.at("format"), 2);
  EXPECT_FALSE(plain_out.contains("sensor")) << "version 2 keeps the sensor per device";
  ASSERT_EQ(plain_out.at("devices").size(), 4u);
  for (const auto& d : plain_out.at("devices")) {
    EXPECT_EQ(d.at("model"), "study") << d.dump();
    EXPECT_FALSE(d.contains("overrides")) << d.dump();
  }

  LayoutState ranged(make_document(default_new_layout()));
  ASSERT_EQ(ranged.open_file(dir / "v1-400.json"), "");
  EXPECT_DOUBLE_EQ(ranged.layout().devices[0].sensor.range_mm, 400.0);
  ASSERT_EQ(ranged.save_to(dir / "ranged.json"), "");
  const nlohmann::json ranged_out = read_json(dir / "ranged.json");
  for (const auto& d : ranged_out.at("devices")) {
    EXPECT_EQ(d.at("model"), "study") << d.dump();
    EXPECT_EQ(d.at("overrides"), nlohmann::json({{"range_mm", 400.0}})) << d.dump();
  }
}

TEST(LayoutFileModels, AMixedRigRoundTripsThroughOpenEditAndSave) {
  const auto dir = test::scratch_dir("layout_mixed_rig");
  HeadlessImGui gui{460, 900};
  auto state = std::make_shared<LayoutState>(make_document(default_new_layout()));
  const char* models[] = {"lmc", "lmc", "lmc2", "lmc2"};
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(set_device_model(state->upd_history(), i, models[i]));
  SensorModel s = state->layout().devices[3].sensor;
  s.range_mm = 900;
  ASSERT_TRUE(set_device_sensor(state->upd_history(), 3, s));
  ASSERT_EQ(state->save_to(dir / "mixed.json"), "");
  const Layout saved = state->history().head().layout;

  auto reopened = std::make_shared<LayoutState>(make_document(default_new_layout()));
  ASSERT_EQ(reopened->open_file(dir / "mixed.json"), "");
  EXPECT_EQ(reopened->layout(), saved);
  EXPECT_FALSE(reopened->unsaved());

  // Edit in the Inspector: LMC1 becomes an LMC2, LMC4 loses its override; save and read again.
  InspectorPanel inspector{reopened};
  const auto body = [&] { inspector.draw(); };
  const auto click = [&](const std::string& anchor) {
    gui.frame(body);
    const auto c = inspector.anchors().centre(anchor);
    ASSERT_TRUE(c.has_value()) << anchor;
    gui.click(c->x, c->y, body);
  };
  reopened->select(0);
  click("model");
  click("model.lmc2");
  reopened->select(3);
  click("reset-sensor");
  EXPECT_TRUE(reopened->unsaved());
  ASSERT_EQ(reopened->save_to(dir / "mixed.json"), "");
  const nlohmann::json j = read_json(dir / "mixed.json");
  const char* expected[] = {"lmc2", "lmc", "lmc2", "lmc2"};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(j.at("devices").at(i).at("model"), expected[i]) << i;
    EXPECT_FALSE(j.at("devices").at(i).contains("overrides")) << j.at("devices").at(i).dump();
  }
  LayoutState third(make_document(default_new_layout()));
  ASSERT_EQ(third.open_file(dir / "mixed.json"), "");
  EXPECT_EQ(third.layout(), reopened->history().head().layout);
}

}  // namespace layout_inspector_models_test
}  // namespace lmc::ui
