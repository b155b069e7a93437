#pragma once
// Agreement as a validation study reports it, over the trials the table shows: per
// layout × pose group and for each finger length and joint range of motion, Bland–Altman bias and
// 95 % limits with their confidence intervals (the repeated-measures form when a subject has
// several trials), RMSE, Pearson r and ICC(2,1) with the model named; the selected measure's
// Bland–Altman plot; and the study's visibility-rate map per controller × motion × layout.
#include <memory>

#include "core/review/agreement_table.h"
#include "ui/model/picture_renderer.h"
#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/png_saver.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewAgreementPanel : public Panel {
 public:
  explicit ReviewAgreementPanel(std::shared_ptr<ReviewState> state) : Panel("##agreement"), state_(std::move(state)) {}
  void draw(const PictureRenderer& renderer);
  // "motion", "group", "export_all" and "measure.N" (the table's rows) as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }
  int measure() const { return measure_; }  // the table's selected row, whose Bland-Altman plot is drawn

 private:
  void draw_motion_choice();
  const AgreementGroup& draw_group_choice(const AgreementTable& table);
  void draw_export_all();
  void draw_what_is_missing(const MeasureAgreement& chosen);
  void draw_figures(const AgreementGroup& group, const PictureRenderer& renderer);

  std::shared_ptr<ReviewState> state_;
  int group_ = -1;  // index into the table's groups; −1: the pooled "all" group (last)
  int measure_ = 0;
  FileBrowser export_browser_{"Export agreement and figures to a new folder", ""};
  PngSaver png_{1000, 700};
  PngSaver map_png_{1000, 600};
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
