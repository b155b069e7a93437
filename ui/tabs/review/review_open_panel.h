#pragma once
// What the Review tab can open: Open folder... (any file of a subject session or a folder of
// trials; its folder opens), the study's sample trial and the demo sessions when they exist.
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewOpenPanel : public Panel {
 public:
  explicit ReviewOpenPanel(std::shared_ptr<ReviewState> state) : Panel("##open"), state_(std::move(state)) {}
  void draw();
  // "open", "sample" and "demo" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::shared_ptr<ReviewState> state_;
  FileBrowser browser_{"Open a folder of trials", ""};
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
