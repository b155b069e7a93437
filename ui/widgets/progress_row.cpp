#include "ui/widgets/progress_row.h"

#include <imgui.h>

#include "ui/widgets/widget_anchors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lmc::ui {

std::string format_duration(double s) {
  char buf[48];
  if (!std::isfinite(s) || s < 0) return "-";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else {
    const long total = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", total / 60, total % 60);
  }
  return buf;
}

bool draw_progress_row(const char* id, double fraction, const std::string& stage, double elapsed_s,
                       std::optional<double> eta_s, bool cancellable, WidgetAnchors* anchors) {
  ImGui::PushID(id);
  char overlay[160];
  std::snprintf(overlay, sizeof overlay, "%s  %.0f %%", stage.c_str(), std::clamp(fraction, 0.0, 1.0) * 100.0);
  const float button_w = cancellable ? ImGui::CalcTextSize("Cancel").x + ImGui::GetStyle().FramePadding.x * 2 + 8 : 0;
  ImGui::ProgressBar(static_cast<float>(std::clamp(fraction, 0.0, 1.0)), ImVec2(-button_w, 0), overlay);
  bool cancel = false;
  if (cancellable) {
    ImGui::SameLine();
    cancel = ImGui::Button("Cancel");
    if (anchors != nullptr) anchors->remember(std::string(id) + ".cancel");
  }
  ImGui::TextDisabled("elapsed %s · remaining %s", format_duration(elapsed_s).c_str(),
                      eta_s ? format_duration(*eta_s).c_str() : "estimating...");
  if (anchors != nullptr) anchors->remember(std::string(id) + ".elapsed");
  ImGui::PopID();
  return cancel;
}

}  // namespace lmc::ui
