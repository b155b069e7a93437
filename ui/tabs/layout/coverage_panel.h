#pragma once
// Controllers × fingers: the share of pose-set frames in which each controller sees each finger;
// per finger the frames seen by nobody; the placement metric M and the c_0 … c_D histogram
// (docs/algorithms/metric.md). Read from the coverage cache, which recomputes only the column of
// a controller that moved, so the table follows a drag.
#include <memory>

#include "ui/model/layout/layout_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class CoveragePanel : public Panel {
 public:
  explicit CoveragePanel(std::shared_ptr<LayoutState> state) : Panel("##coverage"), state_(std::move(state)) {}
  void draw();

 private:
  bool draw_status();
  void draw_table(const Coverage& c) const;
  static void draw_metric(const CoverageSnapshot& snap);
  static void draw_histogram(const Coverage& c);

  std::shared_ptr<LayoutState> state_;
  FileBrowser report_browser_{"Write the layout report into a new folder", ""};
};

}  // namespace lmc::ui
