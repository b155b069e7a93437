#include "ui/widgets/series_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>

#include "ui/model/plot/axis_ticks.h"
#include "ui/model/plot/min_max_decimation.h"
#include "ui/model/plot/series_palette.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"
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

namespace {

// Where the plot stands on screen and what it shows: screen positions from data and back.
struct PlotArea {
  ImVec2 top;     // the widget's top-left (the y tick labels' gutter starts here)
  ImVec2 p0, p1;  // the data area's corners
  float height = 0, plot_w = 0;
  double view_lo = 0, view_hi = 1;  // x
  double y_lo = 0, y_hi = 1;
  float to_x(double x) const { return p0.x + static_cast<float>((x - view_lo) / (view_hi - view_lo)) * plot_w; }
  float to_y(double y) const { return p1.y - static_cast<float>((y - y_lo) / (y_hi - y_lo)) * height; }
};

// The series shown (not hidden in the legend), with their y values as drawn (log10 when asked).
struct ShownSeries {
  std::vector<size_t> index;  // into the series given to draw()
  std::vector<std::span<const double>> xs, ys;
  std::vector<std::vector<double>> log_copies;
};

ImU32 colour_of(const PlotSeries& ps, size_t position) {
  return to_u32(series_colour(ps.colour >= 0 ? ps.colour : static_cast<int>(position)), 1.0F);
}

// Round y ticks with their numbers in the gutter, x ticks with theirs under the plot (when it has
// an x label).
void draw_ticks(ImDrawList* dl, const PlotArea& a, const SeriesPlotOptions& o) {
  dl->PushClipRect(ImVec2(a.top.x, a.top.y - 2), ImVec2(a.p1.x + 1, a.p1.y + ImGui::GetTextLineHeight() + 4), true);
  for (const double t : nice_ticks(a.y_lo, a.y_hi, std::max(2, static_cast<int>(a.height / 40)))) {
    const float y = a.to_y(t);
    dl->AddLine(ImVec2(a.p0.x, y), ImVec2(a.p1.x, y), palette::kPlotGridLine);
    const std::string text = o.log_y ? series_tick_text(std::pow(10.0, t)) : series_tick_text(t);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    // A tick at the very top moves down into the plot's room rather than lose its top half.
    dl->AddText(ImVec2(a.p0.x - size.x - 4, std::max(y - size.y * 0.5F, a.top.y - 2)), palette::kPlotTickText,
                text.c_str());
  }
  for (const double t : nice_ticks(a.view_lo, a.view_hi, std::max(2, static_cast<int>(a.plot_w / 90)))) {
    const float x = a.to_x(t);
    dl->AddLine(ImVec2(x, a.p0.y), ImVec2(x, a.p1.y), palette::kPlotGridLine);
    if (!o.x_label.empty()) {
      // The last tick's number ends at the plot's right edge rather than lose its last digits
      // ("8" for 80).
      const std::string text = series_tick_text(t);
      const float w = ImGui::CalcTextSize(text.c_str()).x;
      dl->AddText(ImVec2(std::min(x - 8, a.p1.x - w), a.p1.y + 2), palette::kPlotTickText, text.c_str());
    }
  }
  dl->PopClipRect();
}

// Each shown series decimated to one min-max stroke per pixel column; missing values as a faint
// band, never a line at zero.
void draw_curves(ImDrawList* dl, const PlotArea& a, const std::vector<PlotSeries>& series, const ShownSeries& shown) {
  const int columns = std::max(1, static_cast<int>(a.plot_w));
  const float column_w = a.plot_w / static_cast<float>(columns);
  for (size_t k = 0; k < shown.index.size(); ++k) {
    const size_t s = shown.index[k];
    const ImU32 colour = colour_of(series[s], s);
    const auto cols = decimate_min_max(shown.xs[k], shown.ys[k], a.view_lo, a.view_hi, columns);
    float prev_x = 0, prev_y = 0;  // where the previous column with data ended (sparse data skip columns)
    for (int c = 0; c < columns; ++c) {
      const PlotColumn& col = cols[static_cast<size_t>(c)];
      const float x = a.p0.x + (static_cast<float>(c) + 0.5F) * column_w;
      if (col.touches_gap && !col.has_data) {
        dl->AddRectFilled(ImVec2(x - column_w * 0.5F, a.p0.y), ImVec2(x + column_w * 0.5F + 0.5F, a.p1.y),
                          palette::kGapBand);
      }
      if (!col.has_data) continue;
      if (col.joins_previous) dl->AddLine(ImVec2(prev_x, prev_y), ImVec2(x, a.to_y(col.y_first)), colour, 1.5F);
      if (col.y_max > col.y_min)
        dl->AddLine(ImVec2(x, a.to_y(col.y_min)), ImVec2(x, a.to_y(col.y_max)), colour, 1.5F);
      else
        dl->AddCircleFilled(ImVec2(x, a.to_y(col.y_min)), 1.2F, colour);
      prev_x = x;
      prev_y = a.to_y(col.y_last);
    }
  }
}

// The shared cursor, in every linked plot, with each shown series' value at it.
void draw_cursor(ImDrawList* dl, const PlotArea& a, double cursor, const std::vector<PlotSeries>& series,
                 const ShownSeries& shown, bool log_y) {
  if (cursor < a.view_lo || cursor > a.view_hi) return;
  const float x = a.to_x(cursor);
  dl->AddLine(ImVec2(x, a.p0.y), ImVec2(x, a.p1.y), palette::kCursorLine);
  float text_y = a.p0.y + 2;
  for (const size_t s : shown.index) {
    const double v = series_value_at(series[s].x, series[s].y, cursor);
    // Read off the axis: decimals for its visible span (a log axis: of the values it spans).
    const std::string value =
        log_y ? value_label(v, std::pow(10.0, a.y_lo), std::pow(10.0, a.y_hi)) : value_label(v, a.y_lo, a.y_hi);
    const std::string text = series[s].name + " " + (std::isfinite(v) ? value : std::string("missing"));
    dl->AddText(ImVec2(x + 4, text_y), colour_of(series[s], s), text.c_str());
    text_y += ImGui::GetTextLineHeight();
  }
}

}  // namespace

// Legend strip above the plot: it never covers a curve; clicking an entry hides or shows it.
void SeriesPlot::draw_legend(const std::vector<PlotSeries>& series, const SeriesPlotOptions& o) {
  for (size_t s = 0; s < series.size(); ++s) {
    const PlotSeries& ps = series[s];
    const ImU32 c = colour_of(ps, s);
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
      dl->AddRect(b0, ImVec2(b0.x + box, b0.y + box), c);
    } else {
      dl->AddRectFilled(b0, ImVec2(b0.x + box, b0.y + box), c);
    }
  }
  if (!o.y_label.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("   %s", o.y_label.c_str());
  }
}

// Wheel zooms about the pointer, drag pans, double-click resets, on the shared range.
void SeriesPlot::handle_input(float plot_left, float plot_w) {
  const ImGuiIO& io = ImGui::GetIO();
  const double view_lo = x_->lo(), view_hi = x_->hi();
  const auto from_x = [&](float px) { return view_lo + (px - plot_left) / plot_w * (view_hi - view_lo); };
  if (ImGui::IsItemHovered()) {
    x_->cursor = from_x(io.MousePos.x);
    if (io.MouseWheel != 0.0F) x_->zoom(from_x(io.MousePos.x), std::pow(0.85, io.MouseWheel));
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) x_->reset();
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    x_->pan(-io.MouseDelta.x / plot_w * (view_hi - view_lo));
  }
}

void SeriesPlot::draw(const char* id, const std::vector<PlotSeries>& series, const SeriesPlotOptions& o) {
  ImGui::PushID(id);
  draw_legend(series, o);
  // Data extent on x over every series (hidden ones too: hiding must not move the view).
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const auto& ps : series) {
    if (ps.x.empty()) continue;
    x_lo = std::min(x_lo, ps.x.front());
    x_hi = std::max(x_hi, ps.x.back());
  }
  if (x_lo <= x_hi) x_->set_extent(x_lo, x_hi);

  PlotArea a;
  a.height = o.height_px;
  a.top = ImGui::GetCursorScreenPos();
  const float width = std::max(120.0F, ImGui::GetContentRegionAvail().x);
  a.p0 = ImVec2(a.top.x + kAxisGutterPx, a.top.y);
  a.p1 = ImVec2(a.top.x + width, a.top.y + a.height);
  a.plot_w = a.p1.x - a.p0.x;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(a.p0, a.p1, palette::kPanelBackground, 3.0F);
  dl->AddRect(a.p0, a.p1, palette::kPanelBorder, 3.0F);
  ImGui::SetCursorScreenPos(a.p0);
  ImGui::InvisibleButton("plot", ImVec2(a.plot_w, a.height));
  // This frame draws the range as it was before the pointer moves it.
  a.view_lo = x_->lo();
  a.view_hi = x_->hi();
  handle_input(a.p0.x, a.plot_w);

  ShownSeries shown;
  for (size_t s = 0; s < series.size(); ++s) {
    if (hidden(series[s].name)) continue;
    shown.index.push_back(s);
    shown.xs.push_back(series[s].x);
    if (o.log_y) {
      std::vector<double> lg(series[s].y.size());
      for (size_t i = 0; i < lg.size(); ++i) lg[i] = series[s].y[i] > 0 ? std::log10(series[s].y[i]) : NAN;
      shown.log_copies.push_back(std::move(lg));
      shown.ys.push_back(shown.log_copies.back());
    } else {
      shown.ys.push_back(series[s].y);
    }
  }
  std::tie(a.y_lo, a.y_hi) = fit_y_range(shown.xs, shown.ys, a.view_lo, a.view_hi);

  draw_ticks(dl, a, o);
  dl->PushClipRect(a.p0, a.p1, true);
  draw_curves(dl, a, series, shown);
  if (x_->cursor) draw_cursor(dl, a, *x_->cursor, series, shown, o.log_y);
  dl->PopClipRect();
  ImGui::SetCursorScreenPos(ImVec2(a.top.x, a.p1.y + (o.x_label.empty() ? 4.0F : ImGui::GetTextLineHeight() + 6.0F)));
  if (!o.x_label.empty()) {
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + kAxisGutterPx);
    ImGui::TextDisabled("%s", o.x_label.c_str());
  }
  ImGui::PopID();
}

}  // namespace lmc::ui
