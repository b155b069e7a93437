#pragma once
// Every opened trial in one table: filters by subject, layout, pose, motion and status,
// sortable headline columns (visibility per controller, finger-length and range-of-motion
// difference, LMC–Vicon lag); a click selects the trial for the trial view. A bar below it drags
// the table taller or shorter.
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewTrialTablePanel : public Panel {
 public:
  explicit ReviewTrialTablePanel(std::shared_ptr<ReviewState> state)
      : Panel("##trial_table"), state_(std::move(state)) {}
  // The filters' line, the table (its height from ui/model/review/trial_table_height.h) and the splitter.
  void draw();
  // "trial.N" for the row of trials()[N] and "splitter", as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  void draw_table(float height_px);  // the filters' line and the table
  void draw_filters();
  void setup_columns(size_t controllers);
  void draw_row(int index, size_t controllers);
  void draw_splitter(float available, float row_px, size_t rows, float table_px);

  std::shared_ptr<ReviewState> state_;
  float dragged_px_ = 0.0F;  // the table's height once the splitter was dragged (0: the default)
  // The columns were wider than the table in the last frame: its horizontal scrollbar takes this
  // much height, which the rows get back.
  float scrollbar_px_ = 0.0F;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
