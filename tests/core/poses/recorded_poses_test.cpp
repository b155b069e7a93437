// Pose sets from recordings (core/poses/recorded_poses.h): the study's real static trial first,
// then recordings made here to hold the skip rules (no hand, NaN, no layout).
#include "core/poses/recorded_poses.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/common/error.h"
#include "core/hand/hand_model.h"
#include "core/hand/palm_axes.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/trc.h"
#include "core/processing/realign.h"
#include "tests/support/reference_data.h"
#include "tests/support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;

lmc::RecordedPoseOptions controller_source(int id) {
  lmc::RecordedPoseOptions o;
  lmc::parse_recorded_pose_source("LMC" + std::to_string(id), o);
  return o;
}

TEST(RecordedPoses, OneControllerOfTheRealStaticTrialIsRealignedWithItsLayout) {
  const auto raw = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(raw);
  const lmc::LmcRecording rec = lmc::read_lmc_recording(raw);
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");  // Naiv_ trials: the initial layout
  const lmc::RecordedPoseSet out = lmc::pose_set_from_recordings({raw}, controller_source(2));
  std::vector<lmc::HandFrame> expected;
  int without_hand = 0;
  for (const auto& r : rec.rows) {
    if (r.device_id != 2) continue;
    if (!r.hand_present) {
      ++without_hand;
      continue;
    }
    lmc::HandFrame f = r;
    lmc::realign_frame(std::span<lmc::Vec3, lmc::kNumHandPoints>(f.points), layout.devices[1].pose.rotation(),
                       layout.devices[1].pose.translation() + layout.devices[1].offset_mm);
    expected.push_back(f);
  }
  ASSERT_GT(expected.size(), 100u);
  ASSERT_EQ(out.set.size(), static_cast<int>(expected.size()));
  EXPECT_EQ(out.frames_skipped, without_hand);
  ASSERT_EQ(out.trials.size(), 1u);
  EXPECT_EQ(out.trials[0].trial, "Naiv_Static101");
  for (size_t j = 0; j < expected.size(); ++j) {
    for (int i = 0; i < lmc::kNumHandPoints; ++i) ASSERT_EQ(out.set.frames[j].point(i), expected[j].point(i));
  }
  // A static trial of pose 1: horizontal, open hand.
  EXPECT_EQ(out.set.labels.front().orientation, lmc::HandOrientation::kHorizontal);
  EXPECT_EQ(out.set.labels.front().motion, lmc::HandMotion::kOpen);
  // The palm above the table, inside the rig (y up, the table top at 0).
  EXPECT_GT(out.set.frames.front().point(lmc::kPalm).y(), 100.0);
  // The reported palm normal agrees with the one estimated from the points (a right hand).
  const lmc::PalmAxes axes = lmc::estimate_palm_axes(out.set.frames.front());
  EXPECT_GT(axes.normal.dot(out.set.frames.front().point(lmc::kPalmNormal)), 0.8);
  EXPECT_GT(axes.direction.dot(out.set.frames.front().point(lmc::kPalmDirection)), 0.8);
  // Provenance names the source, the trial and the counts.
  std::string all;
  for (const auto& line : out.set.provenance) all += line + "\n";
  EXPECT_NE(all.find("LMC2 alone"), std::string::npos) << all;
  EXPECT_NE(all.find("Naiv_Static101 (" + std::to_string(expected.size()) + ")"), std::string::npos) << all;
  EXPECT_NE(all.find(std::to_string(without_hand) + " skipped"), std::string::npos) << all;
}

TEST(RecordedPoses, ViconMarkersOfTheRealTrialGiveEveryCompleteFrameWithEstimatedPalmAxes) {
  const auto trc = lmc::test::reference_file("validation/Naiv_Static101.trc");
  LMC_REQUIRE_REFERENCE_FILE(trc);
  lmc::RecordedPoseOptions o;
  lmc::parse_recorded_pose_source("vicon", o);
  const lmc::RecordedPoseSet out = lmc::pose_set_from_recordings({trc}, o);
  // Every frame of the capture is either kept or counted as skipped; this one has all its markers.
  EXPECT_EQ(out.set.size() + out.frames_skipped, static_cast<int>(lmc::read_trc(trc).positions.size()));
  ASSERT_GE(out.set.size(), 100);
  EXPECT_EQ(out.trials.at(0).palm_axes_estimated, out.set.size());
  for (const auto& f : out.set.frames) {
    EXPECT_NEAR(f.point(lmc::kPalmNormal).norm(), 1.0, 1e-9);
    EXPECT_NEAR(f.point(lmc::kPalmDirection).dot(f.point(lmc::kPalmNormal)), 0.0, 1e-9);
  }
}

TEST(RecordedPoses, EveryNthFrameAndTheTrialPattern) {
  const auto raw = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(raw);
  lmc::RecordedPoseOptions o = controller_source(1);
  const int all =
      lmc::pose_set_from_recordings({raw}, o).set.size() + lmc::pose_set_from_recordings({raw}, o).frames_skipped;
  o.every = 3;
  const lmc::RecordedPoseSet thinned = lmc::pose_set_from_recordings({raw}, o);
  EXPECT_EQ(thinned.set.size() + thinned.frames_skipped, (all + 2) / 3);
  o.trials_glob = "*Index*";
  try {
    (void)lmc::pose_set_from_recordings({raw}, o);
    FAIL() << "no trial matches";
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find("*Index*"), std::string::npos) << e.what();
  }
}

// A raw recording of one controller at the world origin's pose, holding `frames` (device frame).
void write_raw(const fs::path& file, const std::vector<lmc::HandFrame>& frames) {
  lmc::LmcRecording rec;
  rec.kind = lmc::RecordingKind::kRaw;
  std::int64_t t = 1000;
  for (auto f : frames) {
    f.device_id = 1;
    f.frame_rate_hz = 100;
    f.timestamp_us = (t += 10000);
    rec.rows.push_back(f);
  }
  lmc::save_lmc_recording(file, rec);
}

std::vector<lmc::HandFrame> some_hands(int n) {
  lmc::PoseSetSettings s;
  s.frames = n;
  s.seed = 5;
  auto frames = lmc::generate_pose_set(lmc::HandModel(), s).frames;
  for (auto& f : frames) f.point(lmc::kPalm).y() -= 50.0;  // any device-frame coordinates do
  return frames;
}

TEST(RecordedPoses, BadRecordingsAreLeftOutWithACountAndTheirFileNamed) {
  const auto dir = lmc::test::scratch_dir("recorded_poses_bad");
  auto good = some_hands(20);
  good[3].point(lmc::digit_point(lmc::Digit::kRing, lmc::Joint::kEnd)).x() = std::nan("");  // a NaN point
  good[7].hand_present = false;                                                             // no hand
  write_raw(dir / "LMC_Naiv_Index101.raw.txt", good);
  auto none = some_hands(5);
  for (auto& f : none) f.hand_present = false;
  write_raw(dir / "LMC_Naiv_Thumb101.raw.txt", none);
  write_raw(dir / "LMC_pilot_a.raw.txt", some_hands(5));  // neither Naiv_/Opti_ nor a sidecar: no layout

  const lmc::RecordedPoseSet out = lmc::pose_set_from_recordings({dir}, controller_source(1));
  EXPECT_EQ(out.set.size(), 18);
  EXPECT_EQ(out.frames_skipped, 2);
  ASSERT_EQ(out.trials.size(), 1u);
  EXPECT_EQ(out.trials[0].trial, "Naiv_Index101");
  EXPECT_EQ(out.set.labels[0].motion, lmc::HandMotion::kIndexFlexion);
  ASSERT_EQ(out.skipped.size(), 2u);
  std::string all;
  for (const auto& s : out.skipped) all += s + "\n";
  EXPECT_NE(all.find("LMC_Naiv_Thumb101.raw.txt: no frame with a complete hand"), std::string::npos) << all;
  EXPECT_NE(all.find("LMC_pilot_a.raw.txt: no layout"), std::string::npos) << all;

  // Only bad trials: refused, each named.
  try {
    (void)lmc::pose_set_from_recordings({dir / "LMC_Naiv_Thumb101.raw.txt"}, controller_source(1));
    FAIL() << "a recording without a hand must be refused";
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find("LMC_Naiv_Thumb101.raw.txt"), std::string::npos) << e.what();
  }
  // A controller the trial does not have.
  EXPECT_THROW((void)lmc::pose_set_from_recordings({dir / "LMC_Naiv_Index101.raw.txt"}, controller_source(3)),
               lmc::Error);
  // An empty folder: refused, named.
  const auto empty = dir / "empty";
  std::filesystem::create_directories(empty);
  try {
    (void)lmc::pose_set_from_recordings({empty}, lmc::RecordedPoseOptions{});
    FAIL() << "a folder without trials must be refused";
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find(empty.string()), std::string::npos) << e.what();
  }
}

TEST(RecordedPoses, ProvenanceSurvivesThePoseSetFile) {
  const auto dir = lmc::test::scratch_dir("recorded_poses_file");
  write_raw(dir / "LMC_Naiv_Wrist201.raw.txt", some_hands(4));
  const lmc::RecordedPoseSet out = lmc::pose_set_from_recordings({dir}, controller_source(1));
  EXPECT_EQ(out.set.labels[0].orientation, lmc::HandOrientation::kVertical);
  std::stringstream text;
  lmc::write_pose_set(text, out.set);
  const lmc::PoseSet back = lmc::parse_pose_set(text, "mem");
  EXPECT_EQ(back.provenance, out.set.provenance);
  EXPECT_EQ(back.description, out.set.description);
  EXPECT_EQ(back.size(), 4);
}

TEST(RecordedPoses, SourceNames) {
  lmc::RecordedPoseOptions o;
  lmc::parse_recorded_pose_source("lmc4", o);
  EXPECT_EQ(o.source, lmc::RecordedPoseSource::kController);
  EXPECT_EQ(o.controller, 4);
  EXPECT_EQ(lmc::recorded_pose_source_name(o), "LMC4");
  EXPECT_THROW(lmc::parse_recorded_pose_source("LMC9", o), lmc::Error);
  EXPECT_THROW(lmc::parse_recorded_pose_source("kinect", o), lmc::Error);
}

}  // namespace
