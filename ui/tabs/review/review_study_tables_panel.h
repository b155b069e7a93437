#pragma once
// The study's headline tables (lmc report's) over the trials the Review tab's table shows, drawn
// from the state's markdown blocks.
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class ReviewStudyTablesPanel : public Panel {
 public:
  explicit ReviewStudyTablesPanel(std::shared_ptr<const ReviewState> state)
      : Panel("##study_tables"), state_(std::move(state)) {}
  void draw();

 private:
  std::shared_ptr<const ReviewState> state_;
};

}  // namespace lmc::ui
