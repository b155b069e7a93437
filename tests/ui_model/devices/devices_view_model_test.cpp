// The Devices tab's logic without ImGui, as a client of the workbench's one live rig: rows,
// world-frame hands, assignment, test recordings through the one TrialEngine on a worker thread,
// the rig shared by two clients and the workbench's layout followed. Waits poll a condition with a
// generous deadline, never a fixed sleep, so a loaded machine slows the tests but does not fail them.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "tests/support/reference_data.h"
#include "ui/model/devices/devices_view_model.h"
#include "ui/model/workbench_context.h"

namespace lmc::ui {
namespace {

Layout rig_test_layout(const std::string& name) {
  return load_layout(test::asset_file("layouts/" + name + ".json"));
}

std::string whole_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Refreshes until `done` holds or `timeout_s` passes.
bool refresh_until(DevicesViewModel& vm, const std::function<bool()>& done, double timeout_s = 10.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    vm.refresh();
    if (done()) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

bool said(const DevicesViewModel& vm, const std::string& text) {
  for (const auto& m : vm.messages()) {
    if (m.find(text) != std::string::npos) return true;
  }
  return false;
}

// A workbench context whose layout is `layout` (as the Layout tab would publish it).
struct RigFixture {
  WorkbenchContext context;
  DevicesViewModel vm{context.rig()};
  explicit RigFixture(const std::string& layout = "paper-initial") {
    context.layout().publish(rig_test_layout(layout));
  }
};

TEST(DevicesViewModel, SimulatedRigStreamsFourDevicesWithHandsInTheWorldFrame) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  EXPECT_EQ(vm.layout().name, "paper-initial");
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.all_streaming(); }));
  ASSERT_EQ(vm.rows().size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const DeviceRow& r = vm.rows()[i];
    EXPECT_EQ(r.slot, "LMC" + std::to_string(i + 1));
    EXPECT_EQ(r.backend, "sim");
    EXPECT_GT(r.rate_hz, 5.0);
    EXPECT_LT(r.rate_hz, 40.0);
    EXPECT_GE(r.age_ms, 0.0);
    EXPECT_EQ(r.colour, static_cast<int>(i));
  }
  EXPECT_NE(device_colour(0), device_colour(1));
  // Realigned with pose + offset, every device's palm lands near the same world point.
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.hands().size() >= 2; }));
  const Vec3 p0 = vm.hands()[0].world[kPalm];
  for (const auto& h : vm.hands()) EXPECT_LT((h.world[kPalm] - p0).norm(), 20.0) << h.slot;
  EXPECT_NEAR(p0.y(), 150.0, 40.0);  // the hand is about 15 cm above the table
  vm.stop();
  EXPECT_FALSE(vm.running());
  EXPECT_TRUE(vm.rows().empty());
}

TEST(DevicesViewModel, EachRowShowsTheControllersModelAndTrackingMode) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.rows().size() == 4; }));
  for (const DeviceRow& r : vm.rows()) {
    EXPECT_EQ(r.model, "simulated Leap Motion Controller") << r.slot;
    EXPECT_EQ(r.tracking_mode, "desktop") << r.slot << ": every controller of paper-initial looks up";
  }
  // A LeapC controller as the backend announces it: an LMC2 by its product id, and the mode the
  // service answered with.
  devices::DeviceHub* hub = vm.rig().hub();
  ASSERT_NE(hub, nullptr);
  devices::DeviceEvent appeared;
  appeared.kind = devices::DeviceEventKind::kAppeared;
  appeared.info = {"LP22222", "leapc", "Leap Motion Controller 2", "", 0x1206};
  hub->on_device_event(appeared);
  devices::DeviceEvent mode;
  mode.kind = devices::DeviceEventKind::kTrackingMode;
  mode.info.serial = "LP22222";
  mode.info.tracking_mode = "screen-top";
  hub->on_device_event(mode);
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.rows().size() == 5; }));
  const DeviceRow& lmc2 = vm.rows().back();
  EXPECT_EQ(lmc2.serial, "LP22222");
  EXPECT_EQ(lmc2.model, "Leap Motion Controller 2");
  EXPECT_EQ(lmc2.tracking_mode, "screen-top");
  EXPECT_EQ(lmc2.model_warning, "");  // unassigned: no slot model to differ from
  // In a slot laid out as the study's original controller, the LMC2 is flagged.
  EXPECT_EQ(vm.assign("LP22222", "LMC1"), "");
  ASSERT_TRUE(refresh_until(vm, [&] {
    for (const DeviceRow& r : vm.rows())
      if (r.serial == "LP22222") return !r.model_warning.empty();
    return false;
  }));
  for (const DeviceRow& r : vm.rows()) {
    if (r.serial != "LP22222") continue;
    EXPECT_TRUE(r.warn);
    EXPECT_NE(r.model_warning.find("LMC1 is laid out as a Leap Motion Controller, as the study modelled it"),
              std::string::npos)
        << r.model_warning;
  }
  vm.stop();
}

TEST(DevicesViewModel, SlotAssignmentBindsTheSerialInTheRigsLayout) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.rows().size() == 4; }));
  const std::string serial = vm.rows()[3].serial;
  EXPECT_EQ(vm.assign(serial, "LMC1"), "");
  EXPECT_EQ(vm.layout().devices[0].serial, std::optional<std::string>(serial));
  vm.refresh();
  EXPECT_EQ(vm.rows()[0].serial, serial);
  EXPECT_EQ(vm.rows().back().status, "unassigned");
  EXPECT_NE(vm.assign(serial, "LMC7"), "");
}

TEST(DevicesViewModel, ATestRecordingGoesThroughTheTrialEngine) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  const auto dir = test::scratch_dir("vm_record_engine");
  EXPECT_NE(vm.start_recording(dir, "bad name", 1.0), "");
  ASSERT_EQ(vm.start_recording(dir, "vm_trial", 1.0), "");
  EXPECT_TRUE(vm.recording());
  EXPECT_NE(vm.start_recording(dir, "vm_trial", 1.0), "") << "one trial at a time";
  ASSERT_TRUE(refresh_until(
      vm, [&] { return !vm.recording(); }, 30.0));
  vm.refresh();
  const auto result = vm.rig().trial().result();
  ASSERT_NE(result, nullptr) << vm.rig().trial().error();
  EXPECT_EQ(result->outcome, devices::TrialOutcome::kCompleted) << result->reason;
  EXPECT_EQ(result->trial, "vm_trial");
  const auto progress = vm.recording_progress();
  ASSERT_TRUE(progress.has_value());
  EXPECT_EQ(progress->phase, "done");
  EXPECT_GE(progress->recording_s, 1.0);
  const std::string summary = vm.take_recording_summary();
  EXPECT_EQ(summary.rfind("trial vm_trial completed", 0), 0u) << summary;
  EXPECT_EQ(vm.take_recording_summary(), "") << "told once";
  const RecorderSidecar side = read_recorder_sidecar(dir / "LMC_vm_trial.session.json");
  EXPECT_EQ(side.status, "completed");
  EXPECT_EQ(side.backend, "sim");
  const LmcRecording rec = read_lmc_recording(dir / "LMC_vm_trial.raw.txt");
  EXPECT_GT(rec.rows.size(), 4u);
  EXPECT_TRUE(vm.running()) << "the engine leaves the workbench's running hub running";
}

TEST(DevicesViewModel, RecordingTwiceWithTheSameNameKeepsBothTakes) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  const auto dir = test::scratch_dir("vm_record_twice");
  ASSERT_EQ(vm.start_recording(dir, "test", 0.5), "");
  EXPECT_EQ(vm.recording_trial(), "test");
  ASSERT_TRUE(refresh_until(
      vm, [&] { return !vm.recording(); }, 30.0));
  ASSERT_EQ(vm.take_recording_summary().rfind("trial test completed", 0), 0u);
  const std::string first = whole_file(dir / "LMC_test.raw.txt");
  ASSERT_FALSE(first.empty());

  ASSERT_EQ(vm.start_recording(dir, "test", 0.5), "");
  EXPECT_EQ(vm.recording_trial(), "test-2");
  EXPECT_TRUE(said(vm, "recording test-2 to " + dir.string() + " (test is taken)"));
  ASSERT_TRUE(refresh_until(
      vm, [&] { return !vm.recording(); }, 30.0));
  EXPECT_EQ(vm.take_recording_summary().rfind("trial test-2 completed", 0), 0u);
  EXPECT_EQ(whole_file(dir / "LMC_test.raw.txt"), first) << "the first take is untouched";
  EXPECT_TRUE(std::filesystem::exists(dir / "LMC_test-2.raw.txt"));
  EXPECT_EQ(read_recorder_sidecar(dir / "LMC_test-2.session.json").status, "completed");
}

TEST(DevicesViewModel, StopEndsTheTrialInterruptedAndKeepsItsRows) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  const auto dir = test::scratch_dir("vm_record_stop");
  ASSERT_EQ(vm.start_recording(dir, "stopped", 600.0), "");
  ASSERT_TRUE(refresh_until(vm, [&] {
    const auto p = vm.recording_progress();
    return p && p->phase == "recording" && p->frames_written > 4;
  }));
  vm.stop_recording();
  ASSERT_TRUE(refresh_until(vm, [&] { return !vm.recording(); }));
  const auto result = vm.rig().trial().result();
  ASSERT_NE(result, nullptr);
  EXPECT_EQ(result->outcome, devices::TrialOutcome::kInterrupted);
  EXPECT_NE(vm.take_recording_summary().find("interrupted: stopped by operator"), std::string::npos);
  EXPECT_EQ(read_recorder_sidecar(dir / "LMC_stopped.session.json").status, "completed");
  EXPECT_GT(read_lmc_recording(dir / "LMC_stopped.raw.txt").rows.size(), 4u);
}

TEST(LiveRig, TwoClientsSeeTheSameHubAndTheSameTrial) {
  RigFixture f;
  DevicesViewModel other(f.context.rig());  // e.g. the Record tab
  ASSERT_EQ(f.vm.start("sim"), "");
  EXPECT_TRUE(other.running());
  EXPECT_EQ(other.backend(), "sim");
  ASSERT_NE(f.context.rig().hub(), nullptr);
  EXPECT_EQ(&other.rig(), &f.vm.rig());
  // Frames keep arriving at both clients through the one hub.
  ASSERT_TRUE(refresh_until(other, [&] { return other.rows().size() == 4 && other.rows()[0].frames > 10; }));
  f.vm.refresh();
  ASSERT_EQ(f.vm.rows().size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(f.vm.rows()[i].serial, other.rows()[i].serial);
  // A binding made by one client is the other's too.
  EXPECT_EQ(f.vm.assign(f.vm.rows()[3].serial, "LMC1"), "");
  EXPECT_EQ(other.layout().devices[0].serial, std::optional<std::string>(f.vm.rows()[3].serial));
  EXPECT_EQ(f.vm.assign(f.vm.rows()[3].serial, "LMC4"), "");
  // A trial started by one client is visible to (and blocks) the other.
  const auto dir = test::scratch_dir("rig_shared");
  ASSERT_EQ(f.vm.start_recording(dir, "shared", 600.0), "");
  EXPECT_TRUE(other.recording());
  EXPECT_EQ(other.recording_trial(), "shared");
  EXPECT_NE(other.start_recording(dir, "other", 1.0), "");
  other.stop();  // stopping the rig ends the trial first, keeping its rows
  EXPECT_FALSE(f.vm.running());
  EXPECT_FALSE(f.vm.recording());
  EXPECT_TRUE(std::filesystem::exists(dir / "LMC_shared.raw.txt"));
}

TEST(LiveRig, FollowsTheWorkbenchLayoutWhileStreaming) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.rows().size() == 4; }));
  const std::string bound = vm.rows()[0].serial;
  ASSERT_EQ(vm.assign(bound, "LMC1"), "");

  f.context.layout().publish(rig_test_layout("paper-optimized"));
  vm.refresh();
  EXPECT_EQ(vm.layout().name, "paper-optimized");
  EXPECT_TRUE(vm.running());
  EXPECT_TRUE(said(vm, "layout changed to 'paper-optimized': restarted sim"));
  EXPECT_EQ(vm.layout().devices[0].serial, std::optional<std::string>(bound)) << "bindings survive a layout edit";
  // Streaming again, realigned with the new layout: the hands agree in the world frame.
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.all_streaming() && vm.hands().size() >= 2; }));
  for (const auto& h : vm.hands()) EXPECT_LT((h.world[kPalm] - vm.hands()[0].world[kPalm]).norm(), 20.0) << h.slot;

  // During a trial the change waits for the trial's end.
  const auto dir = test::scratch_dir("rig_layout_during_trial");
  ASSERT_EQ(vm.start_recording(dir, "during", 600.0), "");
  f.context.layout().publish(rig_test_layout("paper-initial"));
  vm.refresh();
  EXPECT_EQ(vm.layout().name, "paper-optimized");
  EXPECT_TRUE(said(vm, "the rig follows when the trial ends"));
  vm.stop_recording();
  ASSERT_TRUE(refresh_until(vm, [&] { return vm.layout().name == "paper-initial"; }));
  EXPECT_TRUE(vm.running());
}

TEST(LiveRig, AStoppedRigStartsWithTheLatestLayout) {
  RigFixture f;
  f.context.layout().publish(rig_test_layout("paper-optimized"));
  ASSERT_EQ(f.vm.start("sim"), "") << "no poll in between";
  EXPECT_EQ(f.vm.layout().name, "paper-optimized");
}

// The paper's table points LMC1 away from the hand: the tab names it and why, so its "no hand" is
// not taken for a broken controller; the layout the authors processed has no such controller.
TEST(DevicesViewModel, NamesAControllerTheLayoutPointsAwayFromTheHand) {
  RigFixture f("paper-optimized");
  DevicesViewModel& vm = f.vm;
  vm.refresh();
  ASSERT_EQ(vm.layout_warnings().size(), 1u);
  const std::string& w = vm.layout_warnings()[0];
  EXPECT_EQ(w.rfind("LMC1 cannot see the hand:", 0), 0u) << w;
  EXPECT_NE(w.find("the hand is outside its field of view"), std::string::npos) << w;
  EXPECT_NE(w.find("layout 'paper-optimized'"), std::string::npos) << w;

  ASSERT_EQ(vm.start("sim"), "");
  const auto lmc1_row = [&]() -> const DeviceRow* {
    for (const auto& r : vm.rows()) {
      if (r.slot == "LMC1") return &r;
    }
    return nullptr;
  };
  ASSERT_TRUE(refresh_until(vm, [&] { return lmc1_row() != nullptr && lmc1_row()->frames > 0; }));
  EXPECT_EQ(lmc1_row()->status, "no hand");
  EXPECT_FALSE(lmc1_row()->hand_present);
  EXPECT_TRUE(lmc1_row()->warn) << "its row stands out beside the warning";

  f.context.layout().publish(rig_test_layout("paper-optimized-as-processed"));
  vm.refresh();
  EXPECT_EQ(vm.layout().name, "paper-optimized-as-processed");
  EXPECT_TRUE(vm.layout_warnings().empty()) << vm.layout_warnings()[0];
  vm.stop();
}

TEST(DevicesViewModel, UnknownBackendIsAnErrorMessage) {
  RigFixture f;
  EXPECT_NE(f.vm.start("bluetooth"), "");
  EXPECT_FALSE(f.vm.running());
  EXPECT_NE(f.vm.messages().back().find("cannot start bluetooth"), std::string::npos);
}

// The Devices tab shows the same fused hand as the Record tab: the rig's hub feeds a live fusion
// worker (devices/fusion/live_fusion.h) with every frame.
TEST(DevicesViewModel, TheRigsControllersAreFusedIntoOneHandWithItsLatency) {
  RigFixture f;
  DevicesViewModel& vm = f.vm;
  EXPECT_FALSE(vm.fused());
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(refresh_until(
      vm,
      [&] {
        return vm.fused() && vm.fused()->has_hand && vm.fusion_stats().window_frames > 20 && vm.hands().size() >= 2;
      },
      30.0));
  // The fused palm lies among the controllers' own palms (they agree within 20 mm, test above).
  const Vec3 fused_palm = vm.fused()->points[kPalm];
  EXPECT_LT((fused_palm - vm.hands()[0].world[kPalm]).norm(), 30.0);
  for (int n : vm.fused()->seen_by) {
    EXPECT_GE(n, 0);
    EXPECT_LE(n, 4);
  }
  const devices::LiveFusionStats& s = vm.fusion_stats();
  EXPECT_EQ(s.frames_refused, 0);
  EXPECT_LE(s.latency_p50_ms, s.latency_p95_ms);
  EXPECT_LE(s.latency_p95_ms, s.latency_max_ms);
  vm.stop();
  vm.refresh();
  EXPECT_FALSE(vm.fused());
  EXPECT_EQ(f.context.rig().fusion(), nullptr);
}

}  // namespace
}  // namespace lmc::ui
