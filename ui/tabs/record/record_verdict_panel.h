#pragma once
// The verdict after each trial (issue #11): pass / warn / fail with the reasons, the key figures
// (recorded span, hand present, per finger how often some controller saw it, per controller rate
// and hand), a small plot of each controller's hand presence and fingers seen over the trial, and
// the operator's Accept [Enter], Redo [R] and Note [N]. Draws and reports the button pressed; the
// keys are the tab's.
#include "ui/model/record/record_session_model.h"

namespace lmc::ui {

enum class VerdictAction { kNone, kAccept, kRedo };

struct NoteInput {
  char text[240] = "";
  bool open = false;   // the note line is shown (N or the button)
  bool focus = false;  // give it the keyboard on the next frame
};

VerdictAction draw_record_verdict_panel(const RecordSessionModel& model, NoteInput& note);

// N: shows the one-line note field and gives it the keyboard.
void open_note(NoteInput& note);
// The note field while open (Enter submits: true; Esc closes it). Also while a trial records:
// the note then waits for the trial's end (RecordSessionModel::add_note).
bool draw_note_line(const RecordSessionModel& model, NoteInput& note);

}  // namespace lmc::ui
