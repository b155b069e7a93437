#pragma once
// One trial on one time axis: the six joint angles and the finger lengths — fused LMC,
// Vicon and, when asked, each controller after realignment — stacked on a shared x range (zoom,
// pan and the cursor move them all), then a label strip per controller × finger so every gap has
// its cause beside it.
#include <map>
#include <memory>
#include <string>

#include "ui/model/picture_renderer.h"
#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_replay_panel.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/png_saver.h"
#include "ui/widgets/series_plot.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewTrialViewPanel : public Panel {
 public:
  explicit ReviewTrialViewPanel(std::shared_ptr<ReviewState> state)
      : Panel("##trial_view"), state_(state), replay_(std::move(state)) {}
  void draw(const PictureRenderer& renderer);
  // "each_controller" and "export_trial" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }
  bool each_controller() const { return each_controller_; }  // each controller's curves drawn too

 private:
  void draw_header(const std::shared_ptr<const TrialView>& view, const PictureRenderer& renderer);
  void draw_plots(const TrialSeries& s);
  // One plot per id, all on the state's shared x range; each keeps its legend toggles.
  SeriesPlot& plot(const std::string& id, const std::shared_ptr<LinkedXRange>& range);
  std::shared_ptr<ReviewState> state_;
  bool each_controller_ = false;
  int finger_ = 1;  // the finger-length plot's finger (0 thumb … 4 pinky)
  // What the curves take besides their four plot areas (legends, combo, axis labels), measured in
  // the last frame: the plots share the rest, so they shrink before anything scrolls.
  float curves_chrome_px_ = 0.0F;
  std::map<std::string, std::unique_ptr<SeriesPlot>> plots_;
  FileBrowser export_browser_{"Export the trial to a new folder", ""};
  ReviewReplayPanel replay_;
  PngSaver png_{1200, 1800};
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
