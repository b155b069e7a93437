#include "ui/tabs/review/review_welcome_panel.h"

#include <imgui.h>

namespace lmc::ui {

void ReviewWelcomePanel::draw() {
  ImGui::Spacing();
  ImGui::TextWrapped(
      "Review processed trials against Vicon: open a subject session (every accepted trial), a folder of trials, or "
      "the "
      "study's sample trial. Trials are resampled, realigned and fused on a worker thread and cached, so opening them "
      "again is instant. Click a trial to see its joint angles and finger lengths against Vicon on one time axis, with "
      "the label strip of every controller explaining each gap; the Agreement view gives Bland-Altman limits, RMSE, "
      "Pearson r and ICC across the trials shown.");
  ImGui::Spacing();
  open_.draw();
}

}  // namespace lmc::ui
