#pragma once
// The Review tab's top bar after the open buttons and Export...: the fusion method, what is open
// (each folder with its finger-length correction and its close button), and the processing batch's
// progress, ETA and Cancel, or what it processed.
#include <filesystem>
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewSourcesPanel : public Panel {
 public:
  explicit ReviewSourcesPanel(std::shared_ptr<ReviewState> state) : Panel("##sources"), state_(std::move(state)) {}
  void draw();
  // The width of the fusion choice that starts draw()'s row (the tab wraps the row before it).
  static float fusion_width();
  // "fusion", "cancel", and per opened folder (by its name) "lengths.NAME", "unlength.NAME" and
  // "close.NAME", as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  // One opened folder as [name  lengths… x]; false when it was closed (the list changed).
  bool folder_chip(const std::filesystem::path& folder);
  void draw_progress();

  std::shared_ptr<ReviewState> state_;
  FileBrowser correction_browser_{"Choose a length correction (lmc length-correction fit)", ".json"};
  std::filesystem::path correction_for_;  // the folder the correction browser chooses for
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
