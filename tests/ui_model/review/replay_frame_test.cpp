// The Review tab's 3D replay frame: the frame nearest the cursor, clamped to the trial;
// controllers with a hand in their slot colour, then Vicon in light grey; the fused hand's
// seen-by counts are the frame's ray-traced labels.
#include <gtest/gtest.h>

#include "ui/model/review/replay_frame.h"

namespace lmc::ui {
namespace replay_frame_test {  // named: test files share unity batches

HandTrack track_with_hand(int frames, bool hand, double x) {
  HandTrack t(frames);
  if (!hand) return t;
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) t.at(f, i) = Vec3(x + f, 100.0 + i, 0.0);
  }
  return t;
}

TEST(ReplayFrame, NearestFrameWithEachControllersHandViconAndSeenByCounts) {
  TrialAnalysis r;
  r.fused = track_with_hand(3, true, 0);
  r.world.frame_count = 3;
  r.world.devices = {
      {1, track_with_hand(3, true, 10)}, {2, track_with_hand(3, false, 0)}, {3, track_with_hand(3, true, 30)}};
  r.has_vicon = true;
  r.vicon = track_with_hand(3, true, 50);
  FingerLabels seen{}, hidden{};
  seen.fill(1);
  hidden.fill(0);
  hidden[1] = 1;  // LMC3 sees only the index finger
  FingerLabels none{};
  none.fill(-1);
  r.labels = {{seen, seen, seen}, {none, none, none}, {hidden, hidden, hidden}};

  const auto f = replay_frame(r, 0.012);  // nearest to frame 1 (0.01 s)
  ASSERT_TRUE(f);
  EXPECT_EQ(f->frame, 1);
  EXPECT_DOUBLE_EQ(f->t_s, 0.01);
  ASSERT_EQ(f->hands.size(), 3u);  // LMC1, LMC3 (LMC2 had no hand), Vicon
  EXPECT_EQ(f->hands[0].slot, "LMC1");
  EXPECT_EQ(f->hands[0].colour, 0);
  EXPECT_DOUBLE_EQ(f->hands[0].world[0].x(), 11.0);
  EXPECT_EQ(f->hands[1].slot, "LMC3");
  EXPECT_EQ(f->hands[1].colour, 2);
  EXPECT_EQ(f->hands[2].slot, "Vicon");
  EXPECT_EQ(f->hands[2].colour, kViconHandColour);
  ASSERT_TRUE(f->fused);
  EXPECT_TRUE(f->fused->has_hand);
  EXPECT_EQ(f->fused->seen_by[0], 1);  // thumb: LMC1 only
  EXPECT_EQ(f->fused->seen_by[1], 2);  // index: LMC1 and LMC3
  // Past either end: the first or the last frame.
  EXPECT_EQ(replay_frame(r, -5.0)->frame, 0);
  EXPECT_EQ(replay_frame(r, 99.0)->frame, 2);
  EXPECT_FALSE(replay_frame(TrialAnalysis{}, 0.0));
}

}  // namespace replay_frame_test
}  // namespace lmc::ui
