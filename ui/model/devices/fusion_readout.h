#pragma once
// The live fusion's latency and drop counts in one line (devices/fusion/live_fusion.h), the same
// words in the Record and Devices tabs.
#include <string>

#include "devices/fusion/live_fusion.h"

namespace lmc::ui {

// "fusion latency (frame arrival to fused hand) p50 0.21 ms · p95 0.40 ms · max 1.3 ms over 2048 frames · 0 dropped for
// display" or, before the first fused frame, "fusion: waiting for frames".
std::string fusion_latency_line(const devices::LiveFusionStats& stats);

}  // namespace lmc::ui
