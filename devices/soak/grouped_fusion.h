#pragma once
// The live fused hand for a rig of any size: a layout holds at most kMaxDevices controllers (the
// fusion, the metrics and the workbench are built for that), so a larger rig is fused in groups of
// up to kMaxDevices consecutive slots, one LiveFusion (live_fusion.h) and worker thread each, as
// that many separate set-ups would be. A hub tap like LiveFusion itself: it renumbers each frame
// into its group and passes it on without waiting.
#include <memory>
#include <vector>

#include "core/layout/layout.h"
#include "devices/frame_tap.h"
#include "devices/fusion/live_fusion.h"

namespace lmc::devices {

class GroupedFusion final : public FrameTap {
 public:
  explicit GroupedFusion(const Layout& layout, LiveFusionOptions options = {});
  ~GroupedFusion() override;

  void tap(const HandFrame& frame) noexcept override;
  void stop();
  int groups() const { return static_cast<int>(groups_.size()); }
  // Summed over the groups (latencies: the worst group's).
  LiveFusionStats stats() const;

 private:
  int devices_ = 0;
  std::vector<std::unique_ptr<LiveFusion>> groups_;
};

// The devices [first, first + count) of `layout` as a layout of their own (slots renumbered from
// 1).
Layout layout_slice(const Layout& layout, int first, int count);

}  // namespace lmc::devices
