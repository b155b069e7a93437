#pragma once
// Under the scene: scrub and play through the pose set's frames, filtered by palm orientation
// (horizontal / vertical) and motion (open, index, thumb, wrist flexion / extension).
#include <memory>

#include "ui/model/layout/layout_tab_state.h"

namespace lmc::ui {

class TimelinePanel {
 public:
  explicit TimelinePanel(std::shared_ptr<LayoutTabState> state) : state_(std::move(state)) {}
  void draw();

 private:
  std::shared_ptr<LayoutTabState> state_;
};

}  // namespace lmc::ui
