#include "ui/widgets/calibration_result_view.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "ui/model/devices/calibration_step.h"
#include "ui/widgets/imgui_colour.h"

namespace lmc::ui {
namespace {

const ImVec4 kCalibrationWarningRed(1.0F, 0.38F, 0.33F, 1.0F);
const ImVec4 kCalibrationGood(0.55F, 0.9F, 0.55F, 1.0F);

std::string calibration_mm_text(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

}  // namespace

void draw_calibration_result(const std::string& trial, const CalibrationResult& r,
                             const std::vector<std::string>& file_warnings, const std::vector<std::string>& notes) {
  ImGui::TextWrapped("Trial %s, %s", trial.c_str(),
                     r.with_vicon ? "against Vicon" : "controllers against each other (no Vicon)");
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (ImGui::BeginTable("calibration", 5, flags)) {
    ImGui::TableSetupColumn("Slot");
    ImGui::TableSetupColumn("Samples");
    ImGui::TableSetupColumn("RMS mm");
    ImGui::TableSetupColumn("Moved mm");
    ImGui::TableSetupColumn("Turned deg");
    ImGui::TableHeadersRow();
    const auto rows = calibration_rows(r);
    for (size_t i = 0; i < rows.size(); ++i) {
      const CalibrationRow& row = rows[i];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(device_colour_u32(static_cast<int>(i))), "%s",
                         row.slot.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%d", row.samples);
      if (row.beyond_cut > 0 && ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "%d of its samples had a coordinate clamped at the controller's axis cut: "
            "only their other coordinates were used",
            row.beyond_cut);
      }
      ImGui::TableNextColumn();
      const std::string rms = calibration_mm_text(row.before_mm) + " > " + calibration_mm_text(row.after_mm);
      ImGui::TextUnformatted(rms.c_str());
      ImGui::TableNextColumn();
      if (row.fitted) {
        ImGui::Text("%.1f", row.moved_mm);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", row.turned_deg);
      } else {
        ImGui::TextColored(kCalibrationWarningRed, "not");
        ImGui::TableNextColumn();
        ImGui::TextColored(kCalibrationWarningRed, "calibrated");
      }
    }
    ImGui::EndTable();
  }
  const std::string disagreement =
      "Disagreement between controllers: " + calibration_mm_text(r.disagreement_before_mm) + " > " +
      calibration_mm_text(r.disagreement_after_mm) + " mm RMS";
  ImGui::TextWrapped("%s", disagreement.c_str());
  const auto warnings = r.all_warnings();
  if (warnings.empty()) ImGui::TextColored(kCalibrationGood, "No warnings.");
  for (const auto& w : file_warnings) ImGui::TextColored(kCalibrationWarningRed, "%s", w.c_str());
  for (const auto& w : warnings) {
    ImGui::PushStyleColor(ImGuiCol_Text, kCalibrationWarningRed);
    ImGui::TextWrapped("%s", w.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", calibration_residuals_explanation());
  for (const auto& n : notes) ImGui::TextWrapped("note: %s", n.c_str());
  for (const auto& n : r.notes) ImGui::TextWrapped("note: %s", n.c_str());
  ImGui::PopStyleColor();
}

}  // namespace lmc::ui
