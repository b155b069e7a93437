#include "ui/tabs/review/review_study_tables_panel.h"

#include <imgui.h>

#include "ui/widgets/markdown_view.h"

namespace lmc::ui {

void ReviewStudyTablesPanel::draw() {
  const auto& blocks = state_->agreement().study_tables;
  if (blocks.empty()) ImGui::TextDisabled("No processed trial among those shown.");
  draw_markdown_view("study_tables", blocks);
}

}  // namespace lmc::ui
