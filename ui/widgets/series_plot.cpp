#include "ui/widgets/series_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "ui/model/plot/axis_ticks.h"
#include "ui/model/plot/min_max_decimation.h"
#include "ui/model/plot/series_palette.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/plot_frame.h"

namespace lmc::ui {
namespace {

constexpr float kAxisGutterPx = kSeriesPlotGutterPx;

std::string series_tick_text(double v) {
  char buf[32];
  const double a = std::abs(v);
  const bool whole = std::abs(v - std::round(v)) < 1e-9;
  std::snprintf(buf, sizeof buf, a != 0 && (a < 0.01 || a >= 1e5) ? "%.2g" : (a < 10 && !whole ? "%.2f" : "%.0f"), v);
  return buf;
}

// The y value of the sample nearest to x (NaN when the nearest is missing or there is none).
double series_value_at(std::span<const double> xs, std::span<const double> ys, double x) {
  if (xs.empty()) return std::numeric_limits<double>::quiet_NaN();
  auto it = std::lower_bound(xs.begin(), xs.end(), x);
  size_t i = static_cast<size_t>(it - xs.begin());
  if (i == xs.size() || (i > 0 && x - xs[i - 1] < xs[i] - x)) i = i == 0 ? 0 : i - 1;
  return ys[i];
}

}  // namespace

bool SeriesPlot::hidden(const std::string& name) const {
  const auto it = hidden_.find(name);
  return it != hidden_.end() && it->second;
}

void SeriesPlot::draw(const char* id, const std::vector<PlotSeries>& series, const SeriesPlotOptions& o) {
  ImGui::PushID(id);
  // Legend strip above the plot: it never covers a curve; clicking an entry hides or shows it.
  for (size_t s = 0; s < series.size(); ++s) {
    const PlotSeries& ps = series[s];
    const Rgba& c = series_colour(ps.colour >= 0 ? ps.colour : static_cast<int>(s));
    if (s > 0) ImGui::SameLine();
    const bool off = hidden(ps.name);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float box = ImGui::GetTextLineHeight() * 0.7F;
    ImGui::PushID(static_cast<int>(s));
    const std::string label = "    " + ps.name;
    if (ImGui::Selectable(label.c_str(), !off, 0, ImVec2(ImGui::CalcTextSize(label.c_str()).x, 0)))
      hidden_[ps.name] = !off;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Click to %s %s", off ? "show" : "hide", ps.name.c_str());
    ImGui::PopID();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 b0(at.x + 2, at.y + (ImGui::GetTextLineHeight() - box) * 0.5F);
    if (off) {
      dl->AddRect(b0, ImVec2(b0.x + box, b0.y + box), to_u32(c, 1.0F));
    } else {
      dl->AddRectFilled(b0, ImVec2(b0.x + box, b0.y + box), to_u32(c, 1.0F));
    }
  }
  if (!o.y_label.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("   %s", o.y_label.c_str());
  }

  // Data extent on x over every series (hidden ones too: hiding must not move the view).
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const auto& ps : series) {
    if (ps.x.empty()) continue;
    x_lo = std::min(x_lo, ps.x.front());
    x_hi = std::max(x_hi, ps.x.back());
  }
  if (x_lo <= x_hi) x_->set_extent(x_lo, x_hi);

  const float height = o.height_px;
  const ImVec2 top = ImGui::GetCursorScreenPos();
  const float width = std::max(120.0F, ImGui::GetContentRegionAvail().x);
  const ImVec2 p0(top.x + kAxisGutterPx, top.y);
  const ImVec2 p1(top.x + width, top.y + height);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(p0, p1, IM_COL32(24, 26, 30, 255), 3.0F);
  dl->AddRect(p0, p1, IM_COL32(80, 84, 92, 255), 3.0F);
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("plot", ImVec2(p1.x - p0.x, height));
  const bool hovered = ImGui::IsItemHovered();
  const float plot_w = p1.x - p0.x;
  const double view_lo = x_->lo(), view_hi = x_->hi();
  const auto to_x = [&](double x) { return p0.x + static_cast<float>((x - view_lo) / (view_hi - view_lo)) * plot_w; };
  const auto from_x = [&](float px) { return view_lo + (px - p0.x) / plot_w * (view_hi - view_lo); };

  // Interaction on the shared range: wheel zooms about the pointer, drag pans, double-click resets.
  const ImGuiIO& io = ImGui::GetIO();
  if (hovered) {
    x_->cursor = from_x(io.MousePos.x);
    if (io.MouseWheel != 0.0F) x_->zoom(from_x(io.MousePos.x), std::pow(0.85, io.MouseWheel));
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) x_->reset();
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    x_->pan(-io.MouseDelta.x / plot_w * (view_hi - view_lo));
  }

  // The y values as drawn (log10 when asked), and the y range of what is visible.
  std::vector<std::vector<double>> log_copies;
  std::vector<std::span<const double>> xs, ys;
  std::vector<size_t> shown;
  for (size_t s = 0; s < series.size(); ++s) {
    if (hidden(series[s].name)) continue;
    shown.push_back(s);
    xs.push_back(series[s].x);
    if (o.log_y) {
      std::vector<double> lg(series[s].y.size());
      for (size_t i = 0; i < lg.size(); ++i) lg[i] = series[s].y[i] > 0 ? std::log10(series[s].y[i]) : NAN;
      log_copies.push_back(std::move(lg));
      ys.push_back(log_copies.back());
    } else {
      ys.push_back(series[s].y);
    }
  }
  const auto [y_lo, y_hi] = fit_y_range(xs, ys, view_lo, view_hi);
  const auto to_y = [&](double y) { return p1.y - static_cast<float>((y - y_lo) / (y_hi - y_lo)) * height; };

  dl->PushClipRect(ImVec2(top.x, top.y - 2), ImVec2(p1.x + 1, p1.y + ImGui::GetTextLineHeight() + 4), true);
  for (const double t : nice_ticks(y_lo, y_hi, std::max(2, static_cast<int>(height / 40)))) {
    const float y = to_y(t);
    dl->AddLine(ImVec2(p0.x, y), ImVec2(p1.x, y), kPlotGridLine);
    const std::string text = o.log_y ? series_tick_text(std::pow(10.0, t)) : series_tick_text(t);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    // A tick at the very top moves down into the plot's room rather than lose its top half.
    dl->AddText(ImVec2(p0.x - size.x - 4, std::max(y - size.y * 0.5F, top.y - 2)), kPlotTickText, text.c_str());
  }
  for (const double t : nice_ticks(view_lo, view_hi, std::max(2, static_cast<int>(plot_w / 90)))) {
    const float x = to_x(t);
    dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), kPlotGridLine);
    if (!o.x_label.empty()) {
      // The last tick's number ends at the plot's right edge rather than lose its last digits
      // ("8" for 80).
      const std::string text = series_tick_text(t);
      const float w = ImGui::CalcTextSize(text.c_str()).x;
      dl->AddText(ImVec2(std::min(x - 8, p1.x - w), p1.y + 2), kPlotTickText, text.c_str());
    }
  }
  dl->PopClipRect();

  dl->PushClipRect(p0, p1, true);
  const int columns = std::max(1, static_cast<int>(plot_w));
  const float column_w = plot_w / static_cast<float>(columns);
  for (size_t k = 0; k < shown.size(); ++k) {
    const size_t s = shown[k];
    const PlotSeries& ps = series[s];
    const ImU32 colour = to_u32(series_colour(ps.colour >= 0 ? ps.colour : static_cast<int>(s)), 1.0F);
    const auto cols = decimate_min_max(xs[k], ys[k], view_lo, view_hi, columns);
    float prev_x = 0, prev_y = 0;  // where the previous column with data ended (sparse data skip columns)
    for (int c = 0; c < columns; ++c) {
      const PlotColumn& col = cols[static_cast<size_t>(c)];
      const float x = p0.x + (static_cast<float>(c) + 0.5F) * column_w;
      if (col.touches_gap && !col.has_data) {
        // Missing values: a faint band, never a line at zero.
        dl->AddRectFilled(ImVec2(x - column_w * 0.5F, p0.y), ImVec2(x + column_w * 0.5F + 0.5F, p1.y),
                          IM_COL32(120, 120, 140, 28));
      }
      if (!col.has_data) continue;
      if (col.joins_previous) dl->AddLine(ImVec2(prev_x, prev_y), ImVec2(x, to_y(col.y_first)), colour, 1.5F);
      if (col.y_max > col.y_min)
        dl->AddLine(ImVec2(x, to_y(col.y_min)), ImVec2(x, to_y(col.y_max)), colour, 1.5F);
      else
        dl->AddCircleFilled(ImVec2(x, to_y(col.y_min)), 1.2F, colour);
      prev_x = x;
      prev_y = to_y(col.y_last);
    }
  }
  // The shared cursor, in every linked plot, with each shown series' value at it.
  if (x_->cursor && *x_->cursor >= view_lo && *x_->cursor <= view_hi) {
    const float x = to_x(*x_->cursor);
    dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), IM_COL32(230, 230, 230, 140));
    float text_y = p0.y + 2;
    for (size_t k = 0; k < shown.size(); ++k) {
      const size_t s = shown[k];
      const double v = series_value_at(series[s].x, series[s].y, *x_->cursor);
      // Read off the axis: decimals for its visible span (a log axis: of the values it spans).
      const std::string value =
          o.log_y ? value_label(v, std::pow(10.0, y_lo), std::pow(10.0, y_hi)) : value_label(v, y_lo, y_hi);
      const std::string text = series[s].name + " " + (std::isfinite(v) ? value : std::string("missing"));
      dl->AddText(ImVec2(x + 4, text_y),
                  to_u32(series_colour(series[s].colour >= 0 ? series[s].colour : static_cast<int>(s)), 1.0F),
                  text.c_str());
      text_y += ImGui::GetTextLineHeight();
    }
  }
  dl->PopClipRect();
  ImGui::SetCursorScreenPos(ImVec2(top.x, p1.y + (o.x_label.empty() ? 4.0F : ImGui::GetTextLineHeight() + 6.0F)));
  if (!o.x_label.empty()) {
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + kAxisGutterPx);
    ImGui::TextDisabled("%s", o.x_label.c_str());
  }
  ImGui::PopID();
}

}  // namespace lmc::ui
