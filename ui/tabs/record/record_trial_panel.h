#pragma once
// The Record tab's main panel: the current trial's name, cue and length; the
// pre-flight checklist before a block (green and red lines, override with a typed reason); while
// recording a big red circle, the countdown, elapsed and remaining time and a strip per controller
// (rate, hand, frame age); after a trial its verdict with reasons and Accept / Redo. Draws and
// reports the button pressed; the keyboard is the tab's.
#include <string>

#include "ui/model/record/record_session_model.h"
#include "ui/scene/orbit_camera.h"
#include "ui/tabs/record/record_verdict_panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

enum class TrialPanelAction {
  kNone,
  kPreflight,
  kOverride,
  kStart,
  kStop,
  kAbort,
  kAccept,
  kRedo,
  kNote,
  kCalibrate,
  kApplyCalibration,
  kKeepNominal,   // the block's calibration step (record_calibration_panel.h)
  kReviewSession  // the session is complete: open it in the Review tab
};

struct TrialPanelInput {
  char override_reason[200] = "";
  char nominal_reason[200] = "";  // why a block keeps its nominal layout instead of a calibration
  OrbitCamera camera;             // the live view's
  WidgetAnchors anchors;          // "preflight", "start", "override" as drawn (headless tests click them)
  NoteInput note;                 // N: the one-line note (kNote when submitted)
};

TrialPanelAction draw_record_trial_panel(const RecordSessionModel& model, TrialPanelInput& input);

}  // namespace lmc::ui
