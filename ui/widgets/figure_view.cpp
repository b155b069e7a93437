#include "ui/widgets/figure_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "core/figures/axis_ticks.h"
#include "ui/widgets/palette.h"
#include "ui/widgets/plot_frame.h"

namespace lmc::ui {
namespace {

constexpr float kLeftGutterPx = 52.0F;
constexpr float kRightGutterPx = 120.0F;  // reference-line labels

// A figure's colours are chosen for white paper; on the dark panel a dark colour turns light.
ImU32 on_dark(const Rgb& c, int alpha = 255) {
  const double luminance = (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b) / 255.0;
  if (luminance < 0.35) return IM_COL32(255 - c.r / 3, 255 - c.g / 3, 255 - c.b / 3, alpha);
  return IM_COL32(c.r, c.g, c.b, alpha);
}

std::string axis_title(const Axis& a) {
  return a.unit.empty() ? a.label : a.label + " (" + a.unit + ")";
}

void dashed_line(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 colour, Dash dash) {
  if (dash == Dash::solid) {
    dl->AddLine(a, b, colour, 1.2F);
    return;
  }
  const float on = dash == Dash::dashed ? 7.0F : 2.0F, off = dash == Dash::dashed ? 5.0F : 4.0F;
  for (float x = a.x; x < b.x; x += on + off)
    dl->AddLine(ImVec2(x, a.y), ImVec2(std::min(x + on, b.x), b.y), colour, 1.2F);
}

// Where the figure's axes stand on screen.
struct FigureArea {
  ImVec2 p0, p1;
  AxisRange xr, yr;
  float to_x(double x) const { return p0.x + static_cast<float>((x - xr.lo) / (xr.hi - xr.lo)) * (p1.x - p0.x); }
  float to_y(double y) const { return p1.y - static_cast<float>((y - yr.lo) / (yr.hi - yr.lo)) * (p1.y - p0.y); }
};

// Legend above the plot: it never covers the data.
void draw_legend(const Figure& f) {
  for (size_t s = 0; s < f.series.size(); ++s) {
    if (s > 0) ImGui::SameLine(0, 12);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float box = ImGui::GetTextLineHeight() * 0.6F;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, at.y + 4), ImVec2(at.x + box, at.y + 4 + box),
                                              on_dark(colour_of(f.series[s], s)));
    ImGui::Dummy(ImVec2(box + 2, box));
    ImGui::SameLine();
    ImGui::TextDisabled("%s", f.series[s].name.c_str());
  }
}

// Grid lines with their tick labels, and the reference lines with theirs in the right gutter.
void draw_axes(ImDrawList* dl, const FigureArea& a, const Figure& f, float height_px) {
  const auto yticks = nice_ticks(a.yr.lo, a.yr.hi, std::max(2, static_cast<int>(height_px / 60)));
  for (const double t : yticks) {
    const float y = a.to_y(t);
    if (y < a.p0.y - 1 || y > a.p1.y + 1) continue;
    dl->AddLine(ImVec2(a.p0.x, y), ImVec2(a.p1.x, y), palette::kPlotGridLine);
    const std::string text = tick_label(t, yticks);
    dl->AddText(ImVec2(a.p0.x - ImGui::CalcTextSize(text.c_str()).x - 4, y - ImGui::GetTextLineHeight() * 0.5F),
                palette::kPlotTickText, text.c_str());
  }
  const auto xticks = nice_ticks(a.xr.lo, a.xr.hi, std::max(2, static_cast<int>((a.p1.x - a.p0.x) / 90)));
  for (const double t : xticks) {
    const float x = a.to_x(t);
    if (x < a.p0.x - 1 || x > a.p1.x + 1) continue;
    dl->AddLine(ImVec2(x, a.p0.y), ImVec2(x, a.p1.y), palette::kPlotGridLine);
    dl->AddText(ImVec2(x - 8, a.p1.y + 2), palette::kPlotTickText, tick_label(t, xticks).c_str());
  }
  for (const auto& r : f.references) {
    const float y = a.to_y(r.y);
    if (y < a.p0.y || y > a.p1.y) continue;
    dashed_line(dl, ImVec2(a.p0.x, y), ImVec2(a.p1.x, y), on_dark(r.colour), r.dash);
    dl->AddText(ImVec2(a.p1.x + 4, y - ImGui::GetTextLineHeight() * 0.5F), on_dark(r.colour), r.label.c_str());
  }
}

// Each series as lines and / or points (a missing value is a gap, never a line to 0); returns
// the point nearest the pointer in words, with its squared distance, while `hovered`.
std::pair<std::string, double> draw_series(ImDrawList* dl, const FigureArea& a, const Figure& f, bool hovered) {
  double best_d2 = std::numeric_limits<double>::infinity();
  std::string nearest;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (size_t s = 0; s < f.series.size(); ++s) {
    const Series& ser = f.series[s];
    const ImU32 colour = on_dark(colour_of(ser, s));
    const bool lines = ser.style != SeriesStyle::points;
    const bool points = ser.style != SeriesStyle::line;
    const size_t n = std::min(ser.x.size(), ser.y.size());
    bool have_prev = false;
    ImVec2 prev;
    for (size_t i = 0; i < n; ++i) {
      if (!std::isfinite(ser.x[i]) || !std::isfinite(ser.y[i])) {
        have_prev = false;
        continue;
      }
      const ImVec2 p(a.to_x(ser.x[i]), a.to_y(ser.y[i]));
      if (lines && have_prev) dl->AddLine(prev, p, colour, 1.5F);
      if (points) dl->AddCircleFilled(p, 3.0F, colour);
      prev = p;
      have_prev = true;
      if (!hovered) continue;
      const double d2 = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
      if (d2 < best_d2) {
        best_d2 = d2;
        nearest = ser.name + ": " + axis_title(f.x) + " " + tick_label(ser.x[i], {0.0, 0.01}) + ", " + axis_title(f.y) +
                  " " + tick_label(ser.y[i], {0.0, 0.01});
      }
    }
  }
  return {nearest, best_d2};
}

}  // namespace

void draw_figure_view(const char* id, const Figure& f, float height_px) {
  ImGui::PushID(id);
  if (!f.title.empty()) ImGui::TextUnformatted(f.title.c_str());
  draw_legend(f);
  FigureArea a;
  a.xr = x_range(f);
  a.yr = y_range(f);
  const ImVec2 top = ImGui::GetCursorScreenPos();
  const float width = std::max(200.0F, ImGui::GetContentRegionAvail().x);
  const float tick_h = ImGui::GetTextLineHeight() + 4;
  a.p0 = ImVec2(top.x + kLeftGutterPx, top.y);
  a.p1 = ImVec2(top.x + width - kRightGutterPx, top.y + height_px);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(a.p0, a.p1, palette::kPanelBackground, 3.0F);
  dl->AddRect(a.p0, a.p1, palette::kPanelBorder, 3.0F);
  ImGui::SetCursorScreenPos(a.p0);
  ImGui::InvisibleButton("figure", ImVec2(std::max(1.0F, a.p1.x - a.p0.x), height_px));
  const bool hovered = ImGui::IsItemHovered();
  draw_axes(dl, a, f, height_px);
  dl->PushClipRect(a.p0, a.p1, true);
  const auto [nearest, best_d2] = draw_series(dl, a, f, hovered);
  dl->PopClipRect();
  if (hovered && !nearest.empty() && best_d2 < 400.0) ImGui::SetTooltip("%s", nearest.c_str());
  // Axis titles: y above the tick labels at the top-left, x under the ticks.
  ImGui::SetCursorScreenPos(ImVec2(a.p0.x, a.p1.y + tick_h));
  ImGui::TextDisabled("%s", axis_title(f.x).c_str());
  ImGui::SameLine(0, 24);
  ImGui::TextDisabled("y: %s", axis_title(f.y).c_str());
  ImGui::PushTextWrapPos(0.0F);  // a note wider than the view goes on over two lines
  for (const auto& note : f.notes) ImGui::TextDisabled("%s", note.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopID();
}

void draw_figure_filling(const char* id, const Figure& figure) {
  // Under the plot: tick labels, axis titles and the notes.
  const float below = 4.5F * ImGui::GetTextLineHeightWithSpacing();
  draw_figure_view(id, figure, std::max(60.0F, ImGui::GetContentRegionAvail().y - below));
}

void draw_figure_grid_filling(const FigureGrid& grid) {
  ImGui::TextUnformatted(grid.title.c_str());
  const float each =
      (ImGui::GetContentRegionAvail().y - 6) / static_cast<float>(std::max<size_t>(1, grid.panels.size()));
  const float overhead = 2.2F * ImGui::GetTextLineHeightWithSpacing();
  for (size_t k = 0; k < grid.panels.size(); ++k) {
    Figure panel = grid.panels[k];
    panel.x = grid.x;  // the grid's shared axis, labelled under every panel of the picture
    draw_figure_view(("panel" + std::to_string(k)).c_str(), panel, std::max(30.0F, each - overhead));
  }
}

}  // namespace lmc::ui
