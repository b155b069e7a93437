#include "ui/widgets/colour_legend.h"

#include <imgui.h>

#include <cstdio>

#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

void draw_categorical_legend(const std::vector<LegendEntry>& entries) {
  const float swatch = ImGui::GetTextLineHeight();
  for (size_t i = 0; i < entries.size(); ++i) {
    const float item_w = swatch + 6.0f + ImGui::CalcTextSize(entries[i].label.c_str()).x;
    if (i > 0) {
      ImGui::SameLine(0.0f, 14.0f);
      if (ImGui::GetContentRegionAvail().x < item_w) ImGui::NewLine();
    }
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + swatch, p.y + swatch), to_u32(entries[i].colour), 2.0f);
    ImGui::Dummy(ImVec2(swatch, swatch));
    ImGui::SameLine(0.0f, 6.0f);
    ImGui::TextUnformatted(entries[i].label.c_str());
  }
}

void draw_colour_bar(const ColourRange& range, float width_px, double scale, int decimals, const char* unit) {
  const float h = ImGui::GetTextLineHeight() * 0.9f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  constexpr int kSteps = 48;
  const float step = width_px / kSteps;
  for (int i = 0; i < kSteps; ++i) {
    const Rgba a = viridis(static_cast<double>(i) / kSteps), b = viridis(static_cast<double>(i + 1) / kSteps);
    dl->AddRectFilledMultiColor(ImVec2(p.x + i * step, p.y), ImVec2(p.x + (i + 1) * step + 0.5f, p.y + h), to_u32(a),
                                to_u32(b), to_u32(b), to_u32(a));
  }
  dl->AddRect(p, ImVec2(p.x + width_px, p.y + h), palette::kLegendBorder);
  ImGui::Dummy(ImVec2(width_px, h));
  char lo[32], mid[32], hi[32];
  std::snprintf(lo, sizeof lo, "%.*f%s", decimals, range.lo * scale, unit);
  std::snprintf(mid, sizeof mid, "%.*f%s", decimals, 0.5 * (range.lo + range.hi) * scale, unit);
  std::snprintf(hi, sizeof hi, "%.*f%s", decimals, range.hi * scale, unit);
  const float x0 = ImGui::GetCursorPosX();
  ImGui::TextUnformatted(lo);
  ImGui::SameLine(x0 + width_px * 0.5f - ImGui::CalcTextSize(mid).x * 0.5f);
  ImGui::TextUnformatted(mid);
  ImGui::SameLine(x0 + width_px - ImGui::CalcTextSize(hi).x);
  ImGui::TextUnformatted(hi);
}

}  // namespace lmc::ui
