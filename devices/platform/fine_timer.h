#pragma once
// Sleeps short enough for 120 Hz pacing (8.3 ms a frame). Linux sleeps to the microsecond; Windows
// by default wakes threads only every 15.6 ms, so a paced source would deliver frames in bursts.
// While one of these is alive, Windows' timer runs at 1 ms (timeBeginPeriod); on Linux it does
// nothing. Hold one for as long as a thread paces frames.
namespace lmc::devices {

class FineTimerResolution {
 public:
  FineTimerResolution();
  ~FineTimerResolution();
  FineTimerResolution(const FineTimerResolution&) = delete;
  FineTimerResolution& operator=(const FineTimerResolution&) = delete;

 private:
  bool raised_ = false;
};

}  // namespace lmc::devices
