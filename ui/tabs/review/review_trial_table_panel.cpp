#include "ui/tabs/review/review_trial_table_panel.h"

#include <imgui.h>
#include <imgui_internal.h>  // the table's window: does it scroll sideways

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/common/number_format.h"
#include "ui/model/review/trial_table_height.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

// One filter combo, its name before it: "any" or one of the column's values.
void filter_combo(const char* label, std::string& value, const std::vector<std::string>& choices, float width) {
  ImGui::TextUnformatted(label);
  ImGui::SameLine(0, 4);
  ImGui::SetNextItemWidth(width);
  const std::string id = std::string("##") + label;
  if (ImGui::BeginCombo(id.c_str(), value.empty() ? "any" : value.c_str())) {
    if (ImGui::Selectable("any", value.empty())) value.clear();
    for (const auto& c : choices) {
      if (ImGui::Selectable(c.c_str(), c == value)) value = c;
    }
    ImGui::EndCombo();
  }
}

// `signed_value`: a difference, written with its sign; unknown values are a dash, never 0.
void number_cell(double v, int decimals, bool signed_value, const char* suffix = "") {
  if (std::isfinite(v)) {
    ImGui::Text("%s%s", format_readable(v, decimals, signed_value).c_str(), suffix);
  } else {
    ImGui::TextDisabled("-");
  }
}

ImVec4 status_colour(TrialRowStatus s) {
  switch (s) {
    case TrialRowStatus::kOk:
      return palette::kOk;
    case TrialRowStatus::kNoVicon:
      return palette::kWarning;
    case TrialRowStatus::kFailed:
      return palette::kError;
    case TrialRowStatus::kCancelled:
      return palette::kMuted;
  }
  return palette::kWhite;
}

}  // namespace

void ReviewTrialTablePanel::draw() {
  anchors_.clear();  // only what this frame drew
  // The filters' line is drawn above the table, in draw_table.
  const float available = ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeightWithSpacing();
  const float row_px = ImGui::GetFontSize() + 2.0F * ImGui::GetStyle().CellPadding.y;
  const size_t rows = state_->visible_trials().size();
  const float table_px = trial_table_height(available, row_px, rows, dragged_px_);
  draw_table(table_px + scrollbar_px_);
  draw_splitter(available, row_px, rows, table_px);
}

// Subject, layout, pose, motion, status and a trial name: the model filters the rows.
void ReviewTrialTablePanel::draw_filters() {
  ReviewState& state = *state_;
  const auto& trials = state.trials();
  TrialFilter f = state.filter();
  filter_combo("subject", f.subject, distinct_values(trials, TrialColumn::kSubject), 110);
  ImGui::SameLine();
  filter_combo("layout", f.layout, distinct_values(trials, TrialColumn::kLayout), 100);
  ImGui::SameLine();
  filter_combo("pose", f.pose, distinct_values(trials, TrialColumn::kPose), 100);
  ImGui::SameLine();
  filter_combo("motion", f.motion, distinct_values(trials, TrialColumn::kMotion), 90);
  ImGui::SameLine();
  filter_combo("status", f.status, distinct_values(trials, TrialColumn::kStatus), 90);
  ImGui::SameLine();
  char text[64];
  std::snprintf(text, sizeof text, "%s", f.text.c_str());
  ImGui::SetNextItemWidth(120);
  if (ImGui::InputTextWithHint("##name", "trial name", text, sizeof text)) f.text = text;
  if (!(f == state.filter())) state.set_filter(f);
}

// The columns (a visibility column per controller, at most 8), each wide enough for what its cells
// hold, and the sort the user picked by clicking a header.
void ReviewTrialTablePanel::setup_columns(size_t controllers) {
  // A header never ends in "…": each column is at least as wide as its name and the sort arrow
  // ImGui keeps room for.
  const auto header_width = [](const char* name, float width) {
    return std::max(width, ImGui::CalcTextSize(name).x + ImGui::GetFontSize() + ImGui::GetStyle().FramePadding.x);
  };
  const auto fixed = [&header_width](const char* name, float width, TrialColumn id, ImGuiTableColumnFlags extra = 0) {
    ImGui::TableSetupColumn(name, ImGuiTableColumnFlags_WidthFixed | extra, header_width(name, width),
                            static_cast<ImGuiID>(id));
  };
  ImGui::TableSetupScrollFreeze(0, 1);
  // The user ids are TrialColumn values, so a sort spec maps straight to the model's sort.
  fixed("subject", 80, TrialColumn::kSubject, ImGuiTableColumnFlags_DefaultSort);
  fixed("trial", 116, TrialColumn::kTrial);
  fixed("layout", 78, TrialColumn::kLayout);
  fixed("pose", 86, TrialColumn::kPose);
  fixed("motion", 60, TrialColumn::kMotion);
  fixed("status", 80, TrialColumn::kStatus);
  for (size_t d = 0; d < controllers; ++d) {
    const std::string name = "LMC" + std::to_string(d + 1) + " seen";
    ImGui::TableSetupColumn(name.c_str(), ImGuiTableColumnFlags_WidthFixed | ImGuiTableColumnFlags_PreferSortDescending,
                            header_width(name.c_str(), 80),
                            static_cast<ImGuiID>(static_cast<int>(TrialColumn::kVisibility) + static_cast<int>(d)));
  }
  fixed("length diff (mm)", 125, TrialColumn::kLengthDiff);
  fixed("|ROM diff| (deg)", 125, TrialColumn::kRomDiff);
  fixed("lag (ms)", 70, TrialColumn::kLag);
  ImGui::TableHeadersRow();
  if (ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs != nullptr && specs->SpecsDirty) {
    if (specs->SpecsCount > 0) {
      state_->set_sort(TrialSort{static_cast<int>(specs->Specs[0].ColumnUserID),
                                 specs->Specs[0].SortDirection != ImGuiSortDirection_Descending});
    }
    specs->SpecsDirty = false;
  }
}

// One trial's row; its first cell selects it and tells where it came from.
void ReviewTrialTablePanel::draw_row(int index, size_t controllers) {
  ReviewState& state = *state_;
  const ReviewTrial& t = state.trials()[static_cast<size_t>(index)];
  const TrialRow& row = t.row;
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::PushID(index);
  if (ImGui::Selectable(row.subject.c_str(), state.selected() == index, ImGuiSelectableFlags_SpanAllColumns)) {
    state.select(index);
  }
  anchors_.remember("trial." + std::to_string(index));
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::Text("%s  (%s%s)", t.job.lmc.string().c_str(), t.job.vicon ? "with Vicon" : "no Vicon file",
                t.from_cache ? ", from the cache" : "");
    if (!row.error.empty()) ImGui::TextColored(palette::kError, "%s", row.error.c_str());
    for (const auto& w : t.outcome.warnings) ImGui::TextDisabled("%s", w.c_str());
    ImGui::EndTooltip();
  }
  ImGui::PopID();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(row.trial.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(row.layout.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(row.pose.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(row.motion.c_str());
  ImGui::TableNextColumn();
  ImGui::TextColored(status_colour(row.status), "%s%s", trial_row_status_name(row.status),
                     row.warnings > 0 && row.status == TrialRowStatus::kOk ? " (!)" : "");
  for (size_t d = 0; d < controllers; ++d) {
    ImGui::TableNextColumn();
    const double v = d < row.visibility_rate.size() ? row.visibility_rate[d] * 100.0 : std::nan("");
    number_cell(v, 0, false, " %");
  }
  ImGui::TableNextColumn();
  number_cell(row.finger_length_diff_mm, 1, true);
  ImGui::TableNextColumn();
  number_cell(row.rom_abs_diff_deg, 1, false);
  ImGui::TableNextColumn();
  number_cell(row.lag_ms, 0, true);
}

void ReviewTrialTablePanel::draw_table(float height_px) {
  ReviewState& state = *state_;
  const auto& trials = state.trials();
  draw_filters();
  const std::vector<int> rows = state.visible_trials();
  ImGui::SameLine();
  ImGui::TextDisabled("%zu of %zu", rows.size(), trials.size());

  size_t controllers = 0;
  for (const auto& t : trials) controllers = std::max(controllers, t.row.visibility_rate.size());
  controllers = std::min<size_t>(controllers, 8);
  const int fixed_columns = 9;
  const int columns = fixed_columns + static_cast<int>(controllers);
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_Resizable | ImGuiTableFlags_Sortable | ImGuiTableFlags_SizingFixedFit |
                                ImGuiTableFlags_ScrollX;  // a narrow window scrolls the columns, never squeezes them
  // The id holds the column count: a table whose columns changed starts with fresh widths.
  const std::string table_id = "trials##" + std::to_string(columns);
  if (!ImGui::BeginTable(table_id.c_str(), columns, flags, ImVec2(0, height_px))) return;
  setup_columns(controllers);
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(rows.size()));
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) draw_row(rows[static_cast<size_t>(r)], controllers);
  }
  scrollbar_px_ = ImGui::GetCurrentWindow()->ScrollbarX ? ImGui::GetStyle().ScrollbarSize : 0.0F;
  ImGui::EndTable();
}

void ReviewTrialTablePanel::draw_splitter(float available, float row_px, size_t rows, float table_px) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::InvisibleButton("##trial_table_splitter", ImVec2(std::max(1.0F, width), 6.0F));
  anchors_.remember("splitter");
  const bool active = ImGui::IsItemActive();
  if (active && ImGui::GetIO().MouseDelta.y != 0.0F)
    dragged_px_ = trial_table_height(available, row_px, rows, table_px + ImGui::GetIO().MouseDelta.y);
  if (active || ImGui::IsItemHovered()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeNS);
  const ImU32 colour = ImGui::GetColorU32(active                   ? ImGuiCol_SeparatorActive
                                          : ImGui::IsItemHovered() ? ImGuiCol_SeparatorHovered
                                                                   : ImGuiCol_Separator);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(at.x, at.y + 3.0F), ImVec2(at.x + width, at.y + 3.0F), colour, 2.0F);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drag to give the trial table more or fewer rows");
}

}  // namespace lmc::ui
