#pragma once
// Settings and legend of the per-finger table heatmap for the selected controller: on/off, the
// finger (thumb … pinky, all), the mode (share of frames visible / frames added that no other
// controller sees), grid size and extent, fixed 0–100 % or data range, and the sweep's progress.
#include <memory>

#include "ui/model/layout/layout_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class HeatmapPanel : public Panel {
 public:
  explicit HeatmapPanel(std::shared_ptr<LayoutState> state) : Panel("##heatmap_body"), state_(std::move(state)) {}
  void draw();

 private:
  std::shared_ptr<LayoutState> state_;
};

}  // namespace lmc::ui
