// The window's frame pacing: the monitor's rate, a fallback for an unknown or implausible one, 30
// on a software renderer, a steady schedule, and no burst of frames after a slow one.
#include <chrono>

#include <gtest/gtest.h>

#include "ui/model/shell/frame_pacer.h"
#include "ui/scene/software_renderer.h"

namespace lmc::ui {
namespace frame_pacer_test {  // named: test files share unity batches

using std::chrono::milliseconds;
using Clock = FramePacer::Clock;

TEST(FramePacer, HoldsToTheMonitorsRateAndFallsBackTo60) {
  EXPECT_EQ(FramePacer(144).rate_hz(), 144);
  EXPECT_EQ(FramePacer(75).rate_hz(), 75);
  EXPECT_EQ(FramePacer(0).rate_hz(), 60);     // GLFW's "unknown"
  EXPECT_EQ(FramePacer(1).rate_hz(), 60);     // a display that reports nonsense
  EXPECT_EQ(FramePacer(1000).rate_hz(), 60);  // likewise
}

TEST(FramePacer, ASoftwareRendererDrawsAtMost30FramesASecond) {
  EXPECT_EQ(FramePacer(60, true).rate_hz(), 30);
  EXPECT_EQ(FramePacer(0, true).rate_hz(), 30);
  EXPECT_EQ(FramePacer(144, true).rate_hz(), 30);
}

TEST(SoftwareRenderer, KnowsTheCpuRenderersByTheirNames) {
  EXPECT_TRUE(is_software_renderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(is_software_renderer("softpipe"));
  EXPECT_TRUE(is_software_renderer("GDI Generic"));
  EXPECT_TRUE(is_software_renderer("D3D12 (Microsoft Basic Render Driver)"));
  EXPECT_FALSE(is_software_renderer("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
  EXPECT_FALSE(is_software_renderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  EXPECT_FALSE(is_software_renderer(""));
}

TEST(FramePacer, AFastLoopWaitsForEachSlot) {
  FramePacer pacer(50);  // 20 ms a frame
  const Clock::time_point t0 = Clock::now();
  // The first frame starts the schedule: no wait.
  EXPECT_EQ(pacer.next_frame_start(t0), t0);
  // Each later frame that took 2 ms waits for the rest of its 20 ms.
  Clock::time_point start = t0;
  for (int i = 1; i <= 5; ++i) {
    const Clock::time_point next = pacer.next_frame_start(start + milliseconds(2));
    EXPECT_EQ(next, t0 + milliseconds(20 * i));
    start = next;
  }
}

TEST(FramePacer, ASlowFrameMovesTheScheduleInsteadOfCatchingUp) {
  FramePacer pacer(50);
  const Clock::time_point t0 = Clock::now();
  pacer.next_frame_start(t0);
  // A frame that took 75 ms (a file dialog, a swap that blocked): the next one starts at once…
  const Clock::time_point late = t0 + milliseconds(75);
  EXPECT_EQ(pacer.next_frame_start(late), late);
  // …and the one after waits a whole slot from there, not the 5 ms left of an old slot.
  EXPECT_EQ(pacer.next_frame_start(late + milliseconds(1)), late + milliseconds(20));
}

}  // namespace frame_pacer_test
}  // namespace lmc::ui
