#include "ui/model/shell/frame_pacer.h"

#include <algorithm>

namespace lmc::ui {
namespace {

// Below 30 the window feels stuck; above 240 no monitor in a lab refreshes.
constexpr int kFallbackHz = 60;
constexpr int kLowestHz = 30;
constexpr int kHighestHz = 240;
constexpr int kSoftwareRendererHz = 30;

int plausible_rate(int refresh_hz) {
  return refresh_hz >= kLowestHz && refresh_hz <= kHighestHz ? refresh_hz : kFallbackHz;
}

}  // namespace

FramePacer::FramePacer(int refresh_hz, bool software_renderer)
    : rate_hz_(software_renderer ? std::min(plausible_rate(refresh_hz), kSoftwareRendererHz)
                                 : plausible_rate(refresh_hz)),
      interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz_))) {}

FramePacer::Clock::time_point FramePacer::next_frame_start(Clock::time_point now) {
  next_ += interval_;
  // The first frame, or one that overran its slot: start the schedule again from now.
  if (next_ < now) next_ = now;
  return next_;
}

}  // namespace lmc::ui
