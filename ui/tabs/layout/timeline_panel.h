#pragma once
// Under the scene: scrub and play through the pose set's frames, filtered by palm orientation
// (horizontal / vertical) and motion (open, index, thumb, wrist flexion / extension).
#include <memory>

#include "ui/model/layout/layout_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

// Under the scene: one row, or two in a narrow region.
class TimelinePanel : public Panel {
 public:
  explicit TimelinePanel(std::shared_ptr<LayoutState> state) : Panel("##timeline"), state_(std::move(state)) {}
  void draw();
  // Its height in a region this wide: one row, or two when the frame slider would be too narrow
  // to show its frame's description beside the filters (the filters then go under it).
  float height(float width) const;

 private:
  std::shared_ptr<LayoutState> state_;
};

}  // namespace lmc::ui
