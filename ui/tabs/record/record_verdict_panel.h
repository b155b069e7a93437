#pragma once
// The verdict after each trial: pass / warn / fail with the reasons, the key figures
// (recorded span, hand present, per finger how often some controller saw it, per controller rate
// and hand), a small plot of each controller's hand presence and fingers seen over the trial, and
// the operator's Accept [Enter], Redo [R] and Note [N]. Draws and reports the button pressed; the
// keys are the tab's.
#include <imgui.h>

#include <vector>

#include "ui/model/record/record_session_model.h"

namespace lmc::ui {

enum class VerdictAction { kNone, kAccept, kRedo };

struct NoteInput {
  char text[240] = "";
  bool open = false;   // the note line is shown (N or the button)
  bool focus = false;  // give it the keyboard on the next frame
  // The field takes the keyboard a frame or two after N (longer on a loaded machine); what the
  // operator types meanwhile is held here and handed to the field once it has the keyboard, so a
  // fast typist loses no letter and no letter reaches the tab's shortcuts (Space, R) instead.
  std::vector<ImWchar> held;
  int opened_frame = -1;
  double opened_time = 0.0;
  bool took_keyboard = false;
  bool submit_when_typed = false;  // Enter came before the field had the keyboard
  // True while the field has not yet taken the keyboard (bounded to 2 s: a note line that is not
  // drawn in the current state must not silence the shortcuts).
  bool awaiting_keyboard(double now) const { return open && !took_keyboard && now - opened_time < 2.0; }
};

VerdictAction draw_record_verdict_panel(const RecordSessionModel& model, NoteInput& note);

// N (by_key) or the Note button: shows the one-line note field and gives it the keyboard.
void open_note(NoteInput& note, bool by_key = false);
// The note field while open (Enter submits: true; Esc closes it). Also while a trial records:
// the note then waits for the trial's end (RecordSessionModel::add_note).
bool draw_note_line(const RecordSessionModel& model, NoteInput& note);

}  // namespace lmc::ui
