#pragma once
// The Record tab's main panel: the current trial's name, cue and length; the
// pre-flight checklist before a block (green and red lines, override with a typed reason); while
// recording a big red circle, the countdown, elapsed and remaining time and a strip per controller
// (rate, hand, frame age); after a trial its verdict with reasons and Accept / Redo; the block's
// calibration step where the protocol has one. Draws and reports the button pressed; the keyboard
// is the tab's.
#include <memory>

#include "ui/model/record/record_state.h"
#include "ui/scene/orbit_camera.h"
#include "ui/tabs/record/record_calibration_panel.h"
#include "ui/tabs/record/record_device_strips_panel.h"
#include "ui/tabs/record/record_note_panel.h"
#include "ui/tabs/record/record_verdict_panel.h"
#include "ui/tabs/record/trial_panel_action.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class RecordTrialPanel : public Panel {
 public:
  explicit RecordTrialPanel(std::shared_ptr<const RecordState> model);
  RecordTrialPanel(const RecordTrialPanel&) = delete;  // verdict_ holds a reference to note_
  RecordTrialPanel& operator=(const RecordTrialPanel&) = delete;
  TrialPanelAction draw();

  // What the actions need from the operator's typing.
  const char* override_reason() const { return override_reason_; }
  const char* nominal_reason() const { return calibration_.nominal_reason(); }
  RecordNotePanel& note() { return note_; }
  // "preflight", "start", "override" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }
  const RecordVerdictPanel& verdict() const { return verdict_; }
  const RecordCalibrationPanel& calibration() const { return calibration_; }

 private:
  void draw_cues(int trial);
  TrialPanelAction recording_section(int trial);
  TrialPanelAction start_section(int trial);
  TrialPanelAction preflight_section();
  void verdict_section(TrialPanelAction& action);
  void live_view();

  std::shared_ptr<const RecordState> model_;
  char override_reason_[200] = "";
  OrbitCamera camera_;  // the live view's
  WidgetAnchors anchors_;
  RecordNotePanel note_;
  RecordVerdictPanel verdict_;  // after note_: it opens it
  RecordCalibrationPanel calibration_;
  RecordDeviceStripsPanel strips_;
};

}  // namespace lmc::ui
