#pragma once
// The Review tab's top bar: what is open (each folder with its close button), Open…, the study's
// sample trial and the demo session when they exist, the fusion method, and the processing batch's
// progress, ETA and Cancel.
#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {

void draw_review_sources_bar(ReviewState& state, FileBrowser& browser);

// Shown instead of the table while nothing is open: what the tab does and where to start.
void draw_review_welcome(ReviewState& state, FileBrowser& browser);

}  // namespace lmc::ui
