#include "ui/widgets/line_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ui/widgets/plot_frame.h"

namespace lmc::ui {

void draw_line_plot(const char* id, std::span<const double> values, const LinePlotOptions& o) {
  ImGui::PushID(id);
  const PlotFrame frame = begin_plot_frame(o.height_px, 60.0F);
  ImDrawList* dl = frame.draw;
  const ImVec2 p0 = frame.p0, p1 = frame.p1;
  const float width = frame.width;
  const bool hovered = frame.hovered;

  const auto tr = [&](double v) { return o.log_y ? std::log10(v) : v; };
  const auto usable = [&](double v) { return std::isfinite(v) && (!o.log_y || v > 0); };
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values) {
    if (!usable(v)) continue;
    lo = std::min(lo, tr(v));
    hi = std::max(hi, tr(v));
  }
  const int n = std::max<int>(static_cast<int>(values.size()), o.x_extent);
  if (std::isfinite(lo) && n > 0) {
    if (hi - lo < 1e-12) {
      lo -= 0.5;
      hi += 0.5;
    }
    const float pad = 6.0f;
    const auto px = [&](size_t i) { return p0.x + pad + (width - 2 * pad) * (n > 1 ? static_cast<float>(i) / (n - 1) : 0.5f); };
    const auto py = [&](double v) {
      return p1.y - pad - (o.height_px - 2 * pad) * static_cast<float>((tr(v) - lo) / (hi - lo));
    };
    ImVec2 prev;
    bool have_prev = false;
    for (size_t i = 0; i < values.size(); ++i) {
      if (!usable(values[i])) {
        have_prev = false;
        continue;
      }
      const ImVec2 q(px(i), py(values[i]));
      if (have_prev) dl->AddLine(prev, q, IM_COL32(90, 200, 255, 255), 2.0f);
      prev = q;
      have_prev = true;
    }
    if (have_prev) dl->AddCircleFilled(prev, 3.0f, IM_COL32(90, 200, 255, 255));
    char top[64], bottom[64];
    std::snprintf(top, sizeof top, "%.4g", o.log_y ? std::pow(10.0, hi) : hi);
    std::snprintf(bottom, sizeof bottom, "%.4g", o.log_y ? std::pow(10.0, lo) : lo);
    draw_y_range_labels(frame, top, bottom);
    if (o.log_y) dl->AddText(ImVec2(p1.x - 60, p0.y + 2), IM_COL32(120, 125, 135, 255), "log scale");
    if (hovered && !values.empty()) {
      const float t = (ImGui::GetIO().MousePos.x - p0.x - pad) / (width - 2 * pad);
      const auto i = static_cast<size_t>(std::clamp(std::lround(t * (n - 1)), 0L, static_cast<long>(values.size()) - 1));
      char tip[96];
      std::snprintf(tip, sizeof tip, "%.4g", values[i]);
      ImGui::SetTooltip("%s %zu: %s", o.x_label, i, tip);
    }
  } else {
    dl->AddText(ImVec2(p0.x + 8, p0.y + 8), IM_COL32(140, 140, 150, 255), "no data yet");
  }
  ImGui::PopID();
}

}  // namespace lmc::ui
