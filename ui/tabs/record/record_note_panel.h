#pragma once
// N: the one-line note on a trial. Opened by the key or a Note button, it takes the keyboard a
// frame or two later; Enter submits it (the tab journals it through RecordState::add_note,
// which while a trial records keeps it until the trial ends), Esc drops it.
#include <imgui.h>

#include <memory>
#include <vector>

#include "ui/model/record/record_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class RecordNotePanel : public Panel {
 public:
  explicit RecordNotePanel(std::shared_ptr<const RecordState> model) : Panel("##note"), model_(std::move(model)) {}
  // Shows the note field and gives it the keyboard (by_key: N was pressed, and letters typed
  // after it in the same frame are kept).
  void open(bool by_key = false);
  // The note field while open; true in the frame Enter submits it.
  bool draw();
  const char* text() const { return text_; }
  void clear() { reset(); }
  // True while the field has not yet taken the keyboard. Bounded, so that a note line not drawn in
  // the current state cannot silence the shortcuts for good, but by frames as well as by time: on a
  // loaded machine two seconds can pass in a few frames, before the field has had its frame to take
  // the keyboard, and a Space typed into the note then started a trial.
  bool awaiting_keyboard(double now, int frame) const {
    return open_ && !took_keyboard_ && (now - opened_time_ < 2.0 || frame - opened_frame_ < 30);
  }

 private:
  void reset();

  std::shared_ptr<const RecordState> model_;
  char text_[240] = "";
  bool open_ = false;   // the note line is shown (N or the button)
  bool focus_ = false;  // give it the keyboard on the next frame
  // The field takes the keyboard a frame or two after N (longer on a loaded machine); what the
  // operator types meanwhile is held here and handed to the field once it has the keyboard, so a
  // fast typist loses no letter and no letter reaches the tab's shortcuts (Space, R) instead.
  std::vector<ImWchar> held_;
  int opened_frame_ = -1;
  double opened_time_ = 0.0;
  bool took_keyboard_ = false;
  bool submit_when_typed_ = false;  // Enter came before the field had the keyboard
};

}  // namespace lmc::ui
