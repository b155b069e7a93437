#pragma once
// The whole protocol as a list: grouped by layout block, one row per trial with its
// status (pending, recording, pass, warn, fail, interrupted, accepted) and attempt count. A click
// on a row selects that trial for the next Start or redo (not while a trial records).
#include <memory>

#include "ui/model/record/record_state.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class RecordTrialListPanel : public Panel {
 public:
  explicit RecordTrialListPanel(std::shared_ptr<RecordState> model) : Panel("trials"), model_(std::move(model)) {}
  void draw();
  // "trial.N" for the row of trial N as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::shared_ptr<RecordState> model_;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
