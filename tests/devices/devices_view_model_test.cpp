// Devices tab logic without ImGui: rows, world-frame hands, assignment, recording, projection.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/record/trial_name.h"
#include "devices/view/devices_view_model.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace {

Layout paper_initial() { return load_layout(test::asset_file("layouts/paper-initial.json")); }

std::string read_text_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool wait_for(DevicesViewModel& vm, const std::function<bool()>& done, int timeout_ms = 5000) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    vm.refresh();
    if (done()) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

TEST(ViewCamera, ProjectsTheTargetToTheViewportCentreAndRejectsPointsBehind) {
  ViewCamera cam;
  const auto c = cam.project(cam.target, 10, 20, 400, 300);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x(), 210, 1e-9);
  EXPECT_NEAR(c->y(), 170, 1e-9);
  // Up in the world is up on screen (smaller y); behind the eye is not drawn.
  const auto up = cam.project(cam.target + Eigen::Vector3d(0, 50, 0), 10, 20, 400, 300);
  ASSERT_TRUE(up.has_value());
  EXPECT_LT(up->y(), c->y());
  const Eigen::Vector3d behind = cam.eye() + (cam.eye() - cam.target);
  EXPECT_FALSE(cam.project(behind, 0, 0, 400, 300).has_value());
}

TEST(HandBones, ConnectEveryDigitJointAndTheArm) {
  const auto& bones = hand_bones();
  EXPECT_EQ(bones.front(), (std::pair<int, int>{kElbow, kWrist}));
  // 1 arm + 5 × (wrist→meta + 4 joints) + 3 knuckle links.
  EXPECT_EQ(bones.size(), 1u + 5u * 5u + 3u);
  for (const auto& [a, b] : bones) {
    EXPECT_NE(a, kPalmNormal);
    EXPECT_NE(b, kPalmDirection);
  }
  EXPECT_NE(device_colour(0), device_colour(1));
}

TEST(DevicesViewModel, SimulatedRigStreamsFourDevicesWithHandsInTheWorldFrame) {
  DevicesViewModel vm(paper_initial());
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(wait_for(vm, [&] { return vm.all_streaming(); }));
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
  // Realigned with pose + offset, every device's palm lands near the same world point.
  ASSERT_GE(vm.hands().size(), 2u);
  const Vec3 p0 = vm.hands()[0].world[kPalm];
  for (const auto& h : vm.hands()) EXPECT_LT((h.world[kPalm] - p0).norm(), 20.0) << h.slot;
  EXPECT_NEAR(p0.y(), 150.0, 40.0);  // the hand is about 15 cm above the table
  vm.stop();
  EXPECT_FALSE(vm.running());
  EXPECT_TRUE(vm.rows().empty());
}

TEST(DevicesViewModel, SlotAssignmentAndATestRecording) {
  DevicesViewModel vm(paper_initial());
  ASSERT_EQ(vm.start("sim"), "");
  ASSERT_TRUE(wait_for(vm, [&] { return vm.rows().size() == 4; }));
  const std::string serial = vm.rows()[3].serial;
  EXPECT_EQ(vm.assign(serial, "LMC1"), "");
  EXPECT_EQ(vm.layout().devices[0].serial, std::optional<std::string>(serial));
  vm.refresh();
  EXPECT_EQ(vm.rows()[0].serial, serial);
  EXPECT_EQ(vm.rows().back().status, "unassigned");
  EXPECT_NE(vm.assign(serial, "LMC7"), "");

  const auto dir = test::scratch_dir("vm_record");
  EXPECT_NE(vm.start_recording(dir, "bad name"), "");
  ASSERT_EQ(vm.start_recording(dir, "vm_trial"), "");
  EXPECT_TRUE(vm.recording());
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const std::string summary = vm.stop_recording();
  EXPECT_EQ(summary.rfind("recorded ", 0), 0u) << summary;
  EXPECT_FALSE(vm.recording());
  const LmcRecording rec = read_lmc_recording(dir / "LMC_vm_trial.raw.txt");
  EXPECT_GT(rec.rows.size(), 4u);
  for (const auto& r : rec.rows) EXPECT_LE(r.device_id, 3) << "the unassigned device is not recorded";
}

TEST(DevicesViewModel, RecordingTwiceWithTheSameNameKeepsBothTakes) {
  DevicesViewModel vm(paper_initial());
  ASSERT_EQ(vm.start("sim"), "");
  const auto dir = test::scratch_dir("vm_record_twice");
  ASSERT_EQ(vm.start_recording(dir, "test"), "");
  EXPECT_EQ(vm.recording_trial(), "test");
  ASSERT_TRUE(wait_for(vm, [&] { return vm.recording_status()->frames_written > 0; }));
  EXPECT_EQ(vm.stop_recording().rfind("recorded ", 0), 0u);
  const std::string first = read_text_file(dir / "LMC_test.raw.txt");

  ASSERT_EQ(vm.start_recording(dir, "test"), "");
  EXPECT_EQ(vm.recording_trial(), "test-2");
  EXPECT_EQ(vm.messages().back(), "recording test-2 to " + dir.string() + " (test is taken)");
  vm.stop_recording();
  EXPECT_EQ(read_text_file(dir / "LMC_test.raw.txt"), first) << "the first take is untouched";
  EXPECT_TRUE(std::filesystem::exists(dir / "LMC_test-2.raw.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "LMC_test-2.session.json"));
}

TEST(TrialName, NextFreeNameSkipsEveryTakenFileKind) {
  const auto dir = test::scratch_dir("next_free_trial_name");
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T");
  std::ofstream(dir / "LMC_T.raw.txt") << "x";
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T-2");
  std::ofstream(dir / "LMC_T-2.session.json") << "x";
  std::ofstream(dir / "T-3.trc") << "x";
  EXPECT_EQ(next_free_trial_name(dir, "T"), "T-4");
  EXPECT_TRUE(trial_files_exist(dir, "T-3"));
  EXPECT_FALSE(trial_files_exist(dir, "T-4"));
  // A name at the length limit is shortened so that its suffix fits.
  const std::string longest(kMaxTrialNameLength, 'a');
  std::ofstream(dir / ("LMC_" + longest + ".raw.txt")) << "x";
  const std::string next = next_free_trial_name(dir, longest);
  EXPECT_EQ(next, std::string(kMaxTrialNameLength - 2, 'a') + "-2");
  EXPECT_EQ(validate_trial_name(next), "");
  EXPECT_THROW(next_free_trial_name(dir, "../x"), Error);
}

TEST(DevicesViewModel, UnknownBackendIsAnErrorMessage) {
  DevicesViewModel vm(paper_initial());
  EXPECT_NE(vm.start("bluetooth"), "");
  EXPECT_FALSE(vm.running());
  EXPECT_NE(vm.messages().back().find("cannot start bluetooth"), std::string::npos);
}

}  // namespace
}  // namespace lmc::devices
