#pragma once
// How often the workbench's window draws. A swap interval of one waits for the display's refresh,
// but not every display honours it: under Xvfb, in many virtual machines and remote desktops the
// swap returns at once and the loop would draw as fast as the CPU allows (nearly two cores for a
// window nobody is touching). The pacer holds the loop to the monitor's refresh rate whatever the
// swap does; where the swap already waits, its wait is near zero. On a software renderer, where
// each frame of the workbench costs tens of milliseconds of CPU, it holds to 30 frames a second:
// still smooth for an operator, and it leaves the CPU to the recording.
#include <chrono>

namespace lmc::ui {

class FramePacer {
 public:
  using Clock = std::chrono::steady_clock;

  // `refresh_hz` as the monitor reports it; 0 (unknown) or an implausible rate means 60.
  // `software_renderer`: is_software_renderer() of the window's GL renderer.
  explicit FramePacer(int refresh_hz, bool software_renderer = false);

  // The frame rate the pacer holds to.
  int rate_hz() const { return rate_hz_; }

  // Called once a frame has been shown: when the next frame may start. A frame that ran late
  // moves the schedule instead of being followed by a burst of catch-up frames.
  Clock::time_point next_frame_start(Clock::time_point now);

 private:
  int rate_hz_;
  Clock::duration interval_;
  Clock::time_point next_{};
};

}  // namespace lmc::ui
