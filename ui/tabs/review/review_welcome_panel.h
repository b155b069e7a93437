#pragma once
// Shown instead of the Review tab's table while nothing is open: what the tab does and where to
// start (the open buttons).
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_open_panel.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class ReviewWelcomePanel : public Panel {
 public:
  explicit ReviewWelcomePanel(std::shared_ptr<ReviewState> state) : Panel("##welcome"), open_(std::move(state)) {}
  void draw();
  const ReviewOpenPanel& open_panel() const { return open_; }

 private:
  ReviewOpenPanel open_;
};

}  // namespace lmc::ui
