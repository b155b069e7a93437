#pragma once
// Draws the subject screen from its view state (ui/model/record/subject_view.h) over
// the whole of the subject window: the big red circle while recording — the study's cue — or a
// grey one with the countdown in it, the headline, the cue in large letters, how to hold the hand
// and the animated motion pictogram. No controls.
#include "ui/model/record/subject_view.h"
#include "ui/platform/subject_window.h"

namespace lmc::ui {

void draw_subject_screen(const SubjectView& view, const SubjectFonts& fonts);

}  // namespace lmc::ui
