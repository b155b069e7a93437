#include "ui/widgets/label_strips.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/review/trial_series.h"
#include "ui/model/plot/label_runs.h"
#include "ui/widgets/flow_row.h"
#include "ui/widgets/palette.h"
#include "ui/widgets/plot_frame.h"
#include "ui/widgets/series_plot.h"

namespace lmc::ui {
namespace {

// Seen: bluish green; internal model: orange (the palette's own), no hand: the background shows.
ImU32 label_colour(std::int8_t label) {
  return label > 0 ? palette::kLabelSeen : label == 0 ? palette::kLabelModelled : palette::kLabelNoHand;
}

}  // namespace

constexpr float kStripGap = 1.0F, kGroupGap = 5.0F;

float label_strips_height(const std::vector<LabelStrip>& strips, float strip_height_px) {
  float height = 0;
  for (size_t s = 0; s < strips.size(); ++s) {
    height += strip_height_px + kStripGap + (s > 0 && strips[s].group != strips[s - 1].group ? kGroupGap : 0.0F);
  }
  return height;
}

void draw_label_strips(const char* id, std::span<const double> x, const std::vector<LabelStrip>& strips,
                       LinkedXRange& range, float strip_height_px) {
  ImGui::PushID(id);
  const float height = label_strips_height(strips, strip_height_px);
  const ImVec2 top = ImGui::GetCursorScreenPos();
  const float width = std::max(120.0F, ImGui::GetContentRegionAvail().x);
  const ImVec2 p0(top.x + kSeriesPlotGutterPx, top.y);
  const ImVec2 p1(top.x + width, top.y + height);
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("strips", ImVec2(std::max(1.0F, p1.x - p0.x), std::max(1.0F, height)));
  const bool hovered = ImGui::IsItemHovered();
  const float plot_w = p1.x - p0.x;
  const double lo = range.lo(), hi = range.hi();
  const auto to_x = [&](double v) { return p0.x + static_cast<float>((v - lo) / (hi - lo)) * plot_w; };
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImGuiIO& io = ImGui::GetIO();
  const double mouse_x = lo + (io.MousePos.x - p0.x) / plot_w * (hi - lo);
  if (hovered) range.cursor = mouse_x;

  float y = p0.y;
  std::string tooltip;
  for (size_t s = 0; s < strips.size(); ++s) {
    const LabelStrip& strip = strips[s];
    if (s > 0 && strip.group != strips[s - 1].group) y += kGroupGap;
    if (s == 0 || strip.group != strips[s - 1].group) {
      dl->AddText(ImGui::GetFont(), ImGui::GetFontSize() * 0.85F, ImVec2(top.x, y - 2), palette::kPlotTickText,
                  strip.group.c_str());
    }
    dl->AddRectFilled(ImVec2(p0.x, y), ImVec2(p1.x, y + strip_height_px), label_colour(-1));
    dl->PushClipRect(ImVec2(p0.x, y), ImVec2(p1.x, y + strip_height_px), true);
    for (const LabelRun& r : label_runs(x, strip.labels, lo, hi)) {
      if (r.label < 0) continue;
      dl->AddRectFilled(ImVec2(to_x(r.x_from), y),
                        ImVec2(std::max(to_x(r.x_to), to_x(r.x_from) + 1.0F), y + strip_height_px),
                        label_colour(r.label));
    }
    dl->PopClipRect();
    if (hovered && io.MousePos.y >= y - kStripGap && io.MousePos.y < y + strip_height_px + kStripGap && !x.empty()) {
      const auto it = std::lower_bound(x.begin(), x.end(), mouse_x);
      size_t i = static_cast<size_t>(it - x.begin());
      if (i >= x.size()) i = x.size() - 1;
      if (i < strip.labels.size()) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s %s: %s at %.2f s", strip.group.c_str(), strip.name.c_str(),
                      label_word(strip.labels[i]), x[i]);
        tooltip = buf;
      }
    }
    y += strip_height_px + kStripGap;
  }
  if (range.cursor && *range.cursor >= lo && *range.cursor <= hi) {
    const float cx = to_x(*range.cursor);
    dl->AddLine(ImVec2(cx, p0.y), ImVec2(cx, p1.y), palette::kCursorLine);
  }
  if (!tooltip.empty()) ImGui::SetTooltip("%s", tooltip.c_str());
  ImGui::SetCursorScreenPos(ImVec2(top.x, p1.y + 4));
  ImGui::PopID();
}

void draw_label_legend() {
  const struct {
    std::int8_t label;
    const char* text;
  } items[] = {{1, "seen (ray-traced)"}, {0, "internal model (hidden)"}, {-1, "no hand"}};
  bool first = true;
  for (const auto& it : items) {
    const float box = ImGui::GetTextLineHeight() * 0.7F;
    // Beside the last item where it fits, else on the next line (a narrow window).
    const float width = box + 2 + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(it.text).x;
    if (!first) same_line_or_wrap(width, 14);
    first = false;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, at.y + 3), ImVec2(at.x + box, at.y + 3 + box),
                                              label_colour(it.label));
    ImGui::Dummy(ImVec2(box + 2, box));
    ImGui::SameLine();
    ImGui::TextDisabled("%s", it.text);
  }
}

}  // namespace lmc::ui
