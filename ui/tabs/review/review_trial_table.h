#pragma once
// Every opened trial in one table: filters by subject, layout, pose, motion and status,
// sortable headline columns (visibility per controller, finger-length and range-of-motion
// difference, LMC–Vicon lag); a click selects the trial for the trial view.
#include "ui/model/review/review_state.h"

namespace lmc::ui {

void draw_review_trial_table(ReviewState& state, float height_px);

}  // namespace lmc::ui
