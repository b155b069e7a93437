#pragma once
// The Record tab's block calibration, for protocols with a calibration step: before a
// block's first trial, the cues for a still open hand and a button to record it; while it
// records, the time left; then the residual table (the Devices tab's, calibration_result_view.h)
// and the operator's choice: Apply, calibrate again, or keep the nominal layout with a reason.
#include <memory>

#include "ui/model/record/record_state.h"
#include "ui/tabs/record/trial_panel_action.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class RecordCalibrationPanel : public Panel {
 public:
  explicit RecordCalibrationPanel(std::shared_ptr<const RecordState> model)
      : Panel("##calibration"), model_(std::move(model)) {}
  // Call only while the current block needs, records or waits on its calibration.
  TrialPanelAction draw();
  // Why the block keeps its nominal layout (kKeepNominal), as typed.
  const char* nominal_reason() const { return nominal_reason_; }
  // "calibrate", "apply_calibration", "calibrate_again" and "keep_nominal" as drawn.
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  void keep_nominal(TrialPanelAction& action);

  std::shared_ptr<const RecordState> model_;
  char nominal_reason_[200] = "";
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
