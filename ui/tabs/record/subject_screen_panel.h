#pragma once
// Draws the subject screen from the view state the Record tab publishes in the link
// (ui/model/record/subject_view.h) over the whole of the subject window: the big red circle while
// recording — the study's cue — or a grey one with the countdown in it, the headline, the cue in
// large letters, how to hold the hand and the animated motion pictogram. No controls.
#include "ui/model/record/subject_screen_link.h"
#include "ui/platform/subject_window.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class SubjectScreenPanel : public Panel {
 public:
  explicit SubjectScreenPanel(const SubjectScreenLink& link) : Panel("##subject"), link_(link) {}
  // `fonts`: the subject window's (its own ImGui context, drawn in that context's frame).
  void draw(const SubjectFonts& fonts);

 private:
  const SubjectScreenLink& link_;  // the workbench context's, which outlives the window
};

}  // namespace lmc::ui
