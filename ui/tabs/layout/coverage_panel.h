#pragma once
// Controllers × fingers: the share of pose-set frames in which each controller sees each finger;
// per finger the frames seen by nobody; the placement metric M and the c_0 … c_D histogram
// (docs/algorithms/metric.md). Read from the coverage cache, which recomputes only the column of
// a controller that moved, so the table follows a drag.
#include <memory>

#include "ui/model/layout/layout_tab_state.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {

class CoveragePanel {
 public:
  explicit CoveragePanel(std::shared_ptr<LayoutTabState> state) : state_(std::move(state)) {}
  void draw();

 private:
  std::shared_ptr<LayoutTabState> state_;
  FileBrowser report_browser_{"Write the layout report into a new folder", ""};
};

}  // namespace lmc::ui
