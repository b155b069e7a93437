#pragma once
// What a Record panel reports pressed. The tab turns each into the session model's action and its
// status line, the same as the key that means it (Space, Enter, R, N, Esc), so a button and its
// key can never do different things.
namespace lmc::ui {

enum class TrialPanelAction {
  kNone,
  kPreflight,
  kOverride,
  kStart,
  kStop,
  kAbort,
  kAccept,      // asks first (RecordState::ask_accept)
  kKeepAnyway,  // the answer: keep the failed attempt
  kDontKeep,    // the answer: no (the default)
  kRedo,
  kNote,
  kCalibrate,
  kApplyCalibration,
  kKeepNominal,   // the block's calibration step (record_calibration_panel.h)
  kReviewSession  // the session is complete: open it in the Review tab
};

}  // namespace lmc::ui
