#pragma once
// The verdict after each trial: pass / warn / fail with the reasons, the key figures
// (recorded span, hand present, per finger how often some controller saw it, per controller rate
// and hand), a small plot of each controller's hand presence and fingers seen over the trial, and
// the operator's Accept [Enter], Redo [R] and Note [N]. Draws and reports the button pressed; the
// keys are the tab's.
#include <memory>

#include "ui/model/record/record_state.h"
#include "ui/tabs/record/record_note_panel.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

// kAccept asks (Enter); kKeepAnyway and kDontKeep answer the question it opened (Y, Enter/Esc).
enum class VerdictAction { kNone, kAccept, kRedo, kKeepAnyway, kDontKeep };

class RecordVerdictPanel : public Panel {
 public:
  // `note`: the trial panel's note line, which its Note button opens.
  RecordVerdictPanel(std::shared_ptr<const RecordState> model, RecordNotePanel& note)
      : Panel("##verdict"), model_(std::move(model)), note_(note) {}
  VerdictAction draw();
  // "accept", "keep_anyway", "dont_keep", "redo" and "note" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::shared_ptr<const RecordState> model_;
  RecordNotePanel& note_;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
