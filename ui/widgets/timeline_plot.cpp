#include "ui/widgets/timeline_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/widgets/palette.h"
#include "ui/widgets/plot_frame.h"

namespace lmc::ui {

void draw_timeline_plot(const char* id, std::span<const TimelineSeries> series, const TimelinePlotOptions& o) {
  ImGui::PushID(id);
  const PlotFrame frame = begin_plot_frame(o.height_px, 80.0F);
  ImDrawList* dl = frame.draw;
  const ImVec2 p0 = frame.p0, p1 = frame.p1;
  const bool hovered = frame.hovered;

  size_t n = 0;
  for (const auto& s : series) n = std::max(n, s.values.size());
  const float pad = 6.0F;
  const float left = p0.x + 34.0F;  // room for the y labels
  const float right = p1.x - pad;
  const double span = o.y_max > o.y_min ? o.y_max - o.y_min : 1.0;
  const auto px = [&](size_t i) {
    return left + (right - left) * (n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 0.5F);
  };
  const auto py = [&](double v) {
    const double f = std::clamp((v - o.y_min) / span, 0.0, 1.0);
    return p1.y - pad - (o.height_px - 2 * pad) * static_cast<float>(f);
  };
  char top[32], bottom[32], buf[64];
  std::snprintf(top, sizeof top, "%.*f", o.y_decimals, o.y_max);
  std::snprintf(bottom, sizeof bottom, "%.*f", o.y_decimals, o.y_min);
  draw_y_range_labels(frame, top, bottom);
  std::snprintf(buf, sizeof buf, "%.1f s", o.slice_s * static_cast<double>(n));
  dl->AddText(ImVec2(right - ImGui::CalcTextSize(buf).x, p1.y - ImGui::GetTextLineHeight() - 2), palette::kPlotNote,
              buf);

  for (const auto& s : series) {
    const ImU32 colour = ImGui::ColorConvertFloat4ToU32(ImVec4(s.rgb[0], s.rgb[1], s.rgb[2], 1.0F));
    ImVec2 prev;
    bool have_prev = false;
    for (size_t i = 0; i < s.values.size(); ++i) {
      if (!std::isfinite(s.values[i])) {
        have_prev = false;
        continue;
      }
      const ImVec2 q(px(i), py(s.values[i]));
      if (have_prev) dl->AddLine(prev, q, colour, s.thickness);
      prev = q;
      have_prev = true;
    }
  }

  if (hovered && n > 0) {
    const float mx = ImGui::GetIO().MousePos.x;
    const float f = std::clamp((mx - left) / std::max(1.0F, right - left), 0.0F, 1.0F);
    const auto i = static_cast<size_t>(std::lround(f * static_cast<float>(n - 1)));
    dl->AddLine(ImVec2(px(i), p0.y), ImVec2(px(i), p1.y), palette::kHoverLine);
    ImGui::BeginTooltip();
    ImGui::Text("%.2f s", o.slice_s * static_cast<double>(i));
    for (const auto& s : series) {
      if (i >= s.values.size()) continue;
      ImGui::TextColored(ImVec4(s.rgb[0], s.rgb[1], s.rgb[2], 1.0F), "%s: %.2f", s.label.c_str(), s.values[i]);
    }
    ImGui::EndTooltip();
  }
  ImGui::PopID();
}

}  // namespace lmc::ui
