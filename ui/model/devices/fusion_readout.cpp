#include "ui/model/devices/fusion_readout.h"

#include <cstdio>

namespace lmc::ui {

std::string fusion_latency_line(const devices::LiveFusionStats& s) {
  if (s.window_frames == 0) return "fusion: waiting for frames";
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "fusion latency (frame arrival to fused hand) p50 %.2f ms · p95 %.2f ms · max %.2f ms over %zu frames",
                s.latency_p50_ms, s.latency_p95_ms, s.latency_max_ms, s.window_frames);
  std::string line = buf;
  if (s.frames_dropped > 0)
    line += " · " + std::to_string(s.frames_dropped) + " dropped for display (not from the recording)";
  if (s.frames_refused > 0) line += " · " + std::to_string(s.frames_refused) + " refused";
  return line;
}

}  // namespace lmc::ui
