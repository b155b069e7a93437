// The Layout tab on recorded hands: Review's request becomes the tab's pose set (read by the
// store's worker), the coverage runs on it, a load can be cancelled back to the set before, and the
// optimiser's result says how M moved on the recorded poses and on the Monte Carlo set.
#include <gtest/gtest.h>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/lmc_recording.h"
#include "tests/support/scratch_dir.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/last_status.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/layout/optimiser_job.h"
#include "ui/tabs/layout/layout_tab.h"

namespace lmc::ui {
namespace {

using testing::HeadlessImGui;
using testing::LastStatus;

// A processed trial's fused hand (world frame): `frames` of the Monte Carlo generator's hands.
std::filesystem::path write_fused_trial(const std::filesystem::path& dir, const std::string& trial, int frames,
                                        std::uint64_t seed) {
  PoseSetSettings s;
  s.frames = frames;
  s.seed = seed;
  const PoseSet set = generate_pose_set(HandModel(), s);
  LmcRecording rec;
  rec.kind = RecordingKind::kResampled;
  for (size_t j = 0; j < set.frames.size(); ++j) {
    HandFrame f = set.frames[j];
    f.device_id = 1;
    f.frame_rate_hz = 100;
    f.timestamp_us = static_cast<std::int64_t>(j) * 10000;
    rec.rows.push_back(f);
  }
  const auto file = dir / (trial + ".fused.txt");
  save_lmc_recording(file, rec);
  return file;
}

void use_small_monte_carlo(LayoutState& s) {
  PoseSetChoice c;
  c.frames = 30;
  c.seed = 7;
  ASSERT_TRUE(set_pose_set_choice(s.upd_history(), c));
}

TEST(LayoutRecordedPoses, ReviewsTrialsBecomeThePoseSetAndTheCoverageRunsOnThem) {
  HeadlessImGui gui;
  LastStatus status;
  LayoutTab tab(status);
  tab.set_modals_enabled(false);
  tab.state().display.show_heatmap = false;
  use_small_monte_carlo(tab.state());
  const auto dir = lmc::test::scratch_dir("layout_recorded_poses");
  std::vector<std::string> request = {write_fused_trial(dir, "Naiv_Index101", 25, 3).string(),
                                      write_fused_trial(dir, "Naiv_Thumb201", 15, 4).string()};
  tab.take_pose_requests_from(&request);
  gui.frames(1, [&] {
    tab.update(true);
    tab.draw();
  });
  EXPECT_TRUE(request.empty()) << "the tab takes the request once";
  const PoseSetChoice& choice = tab.state().doc().pose_set;
  ASSERT_EQ(choice.source, PoseSetChoice::Source::kRecordings);
  EXPECT_EQ(choice.recordings.size(), 2u);
  EXPECT_EQ(choice.recorded_source, "fused");
  tab.state().poses.wait();
  const PoseSetPtr p = tab.state().poses.current();
  ASSERT_TRUE(p);
  EXPECT_EQ(p->size(), 40);
  EXPECT_EQ(p->vertical.size(), 15u);  // Thumb2…: pose 2, palm left
  ASSERT_FALSE(p->set.provenance.empty());
  EXPECT_NE(p->set.provenance[0].find("fused hand"), std::string::npos);
  for (int i = 0; i < 3; ++i) {
    tab.state().update(0.0);
    tab.state().wait_for_coverage();
  }
  ASSERT_TRUE(tab.state().coverage().latest());
  EXPECT_EQ(tab.state().coverage().latest()->all.frames, 40);
  EXPECT_NE(status.last.find("Pose set: 40 recorded frames"), std::string::npos) << status.last;
  // The Optimiser panel lists where the frames came from.
  gui.frames(2, [&] {
    tab.update(true);
    tab.draw();
  });
  // Undo goes back to the Monte Carlo set: the change was one step.
  tab.state().undo();
  EXPECT_EQ(tab.state().doc().pose_set.source, PoseSetChoice::Source::kMonteCarlo);
}

TEST(LayoutRecordedPoses, CancellingALoadGoesBackToTheSetLoadedBefore) {
  auto state = std::make_shared<LayoutState>(make_document(default_new_layout()));
  state->display.show_heatmap = false;
  use_small_monte_carlo(*state);
  state->update(0.0);
  state->poses.wait();
  ASSERT_TRUE(state->poses.current());
  const PoseSetChoice before = state->doc().pose_set;
  const auto dir = lmc::test::scratch_dir("layout_recorded_poses_cancel");
  std::vector<std::string> files;
  for (int t = 0; t < 12; ++t)
    files.push_back(write_fused_trial(dir, "Naiv_Index1" + std::to_string(10 + t), 400, 10 + t).string());
  ASSERT_TRUE(state->use_recorded_pose_set(files));
  state->update(0.0);  // starts the load
  ASSERT_TRUE(state->poses.loading());
  state->cancel_pose_set_load();
  EXPECT_FALSE(state->poses.loading());
  EXPECT_EQ(state->doc().pose_set, before);
  EXPECT_NE(state->poses.error().find("cancelled"), std::string::npos);
  state->update(0.0);
  EXPECT_FALSE(state->poses.loading()) << "the set before is still loaded: nothing to read again";
  EXPECT_EQ(state->poses.current()->choice, before);
}

TEST(LayoutRecordedPoses, TheOptimiserSaysHowMMovedOnBothSets) {
  OptimiserOutcome o;
  o.start_m = 0.30;
  o.candidate_m = 0.10;
  EXPECT_EQ(specialisation_summary(o), "M on the Monte Carlo set 0.300 -> 0.100 (-0.200).");
  o.has_monte_carlo = true;
  o.start_m_monte_carlo = 0.20;
  o.candidate_m_monte_carlo = 0.25;
  EXPECT_EQ(specialisation_summary(o),
            "M on the poses searched on 0.300 -> 0.100 (-0.200); on the Monte Carlo set 0.200 -> 0.250 (+0.050): "
            "better on these hands, not on the invented ones (specialised).");
  o.candidate_m_monte_carlo = 0.15;
  EXPECT_NE(specialisation_summary(o).find("better on both"), std::string::npos);
}

}  // namespace
}  // namespace lmc::ui
