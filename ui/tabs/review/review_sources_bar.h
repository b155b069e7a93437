#pragma once
// The Review tab's top bar: what is open (each folder with its finger-length correction and its
// close button), Open…, the study's sample trial and the demo session when they exist, Export…, the
// fusion method, and the processing batch's progress, ETA and Cancel.
#include <filesystem>

#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_export_panel.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {

struct ReviewBrowsers {
  FileBrowser folder{"Open a folder of trials", ""};
  FileBrowser correction{"Choose a length correction (lmc length-correction fit)", ".json"};
  std::filesystem::path correction_for;  // the folder the correction browser chooses for
};

void draw_review_sources_bar(ReviewState& state, ReviewBrowsers& browsers, ReviewExportPanel& export_panel);

// Shown instead of the table while nothing is open: what the tab does and where to start.
void draw_review_welcome(ReviewState& state, FileBrowser& browser);

}  // namespace lmc::ui
