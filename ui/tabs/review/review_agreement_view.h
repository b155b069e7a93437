#pragma once
// Agreement as a validation study reports it, over the trials the table shows: per
// layout × pose group and for each finger length and joint range of motion, Bland–Altman bias and
// 95 % limits with their confidence intervals (the repeated-measures form when a subject has
// several trials), RMSE, Pearson r and ICC(2,1) with the model named; the selected measure's
// Bland–Altman plot; and the study's visibility-rate map per controller × motion × layout.
#include "ui/model/picture_renderer.h"
#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/png_saver.h"

namespace lmc::ui {

class ReviewAgreementView {
 public:
  void draw(ReviewState& state, const PictureRenderer& renderer);

 private:
  int group_ = -1;  // index into the table's groups; −1: the pooled "all" group (last)
  int measure_ = 0;
  FileBrowser export_browser_{"Export agreement and figures to a new folder", ""};
  PngSaver png_{1000, 700};
  PngSaver map_png_{1000, 600};
};

}  // namespace lmc::ui
