#include "core/figures/svg_writer.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "core/common/xml_text.h"
#include "core/figures/axis_ticks.h"
#include "core/figures/locale_free_number.h"
#include "core/figures/svg_marks.h"
#include "core/figures/svg_text.h"

namespace lmc {
namespace {

using svg::Box;
using svg::document_start;
using svg::hex;
using svg::kFont;
using svg::kLineHeight;
using svg::kPanelFont;
using svg::Mapper;
using svg::num;
using svg::text;
using svg::text_width;
using svg::title_band;

std::string axis_text(const Axis& a) {
  return a.unit.empty() ? a.label : a.label + " (" + a.unit + ")";
}

std::string dash_attr(Dash d) {
  switch (d) {
    case Dash::dashed:
      return " stroke-dasharray=\"6 4\"";
    case Dash::dotted:
      return " stroke-dasharray=\"2 3\"";
    case Dash::solid:
      break;
  }
  return {};
}

// A legend entry's sample of how its series is drawn.
void swatch(std::string& out, double x, double y, const Series& s, Rgb c) {
  if (s.style != SeriesStyle::points)
    out += "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x + 18) + "\" y2=\"" + num(y) +
           "\" stroke=\"" + hex(c) + "\" stroke-width=\"2\"/>\n";
  if (s.style != SeriesStyle::line)
    out += "<circle cx=\"" + num(x + 9) + "\" cy=\"" + num(y) + "\" r=\"3\" fill=\"" + hex(c) + "\"/>\n";
}

struct LegendItem {
  size_t series;
  double x, row;
};

// Legend entries laid out in rows across `width`, left to right, wrapping; named series only.
std::vector<LegendItem> legend_layout(const Figure& f, double width, int& rows) {
  std::vector<LegendItem> items;
  double x = 0;
  int row = 0;
  for (size_t i = 0; i < f.series.size(); ++i) {
    if (f.series[i].name.empty()) continue;
    const double w = 24 + text_width(f.series[i].name, kFont) + 18;
    if (x > 0 && x + w > width) {
      x = 0;
      ++row;
    }
    items.push_back({i, x, static_cast<double>(row)});
    x += w;
  }
  rows = items.empty() ? 0 : row + 1;
  return items;
}

struct PanelStyle {
  double left = 0;   // room for y tick labels and the y axis label
  double right = 0;  // room for reference-line labels
  bool x_labels = true;
  std::string x_axis_text;
  bool own_title = false;  // a grid panel's title, smaller, inside its area
  int clip_id = 0;
};

double left_margin(const Figure& f) {
  const AxisRange yr = y_range(f);
  const auto ticks = nice_ticks(yr.lo, yr.hi, 5);
  double widest = 0;
  for (const double t : ticks) widest = std::max(widest, text_width(tick_label(t, ticks), kFont));
  return 26 + widest + 8;
}

double right_margin(const Figure& f) {
  double widest = 0;
  for (const ReferenceLine& r : f.references) widest = std::max(widest, text_width(r.label, kFont));
  return widest > 0 ? widest + 16 : 16;
}

// Grid lines and ticks, with the tick labels (the x labels only when the panel shows them).
void draw_grid_and_ticks(std::string& out, const Mapper& m, bool x_labels) {
  const Box& plot = m.plot;
  const AxisRange& xr = m.xr;
  const auto yticks = nice_ticks(m.yr.lo, m.yr.hi, std::max(2, static_cast<int>(plot.h / 50)));
  const auto xticks = nice_ticks(xr.lo, xr.hi, std::max(2, static_cast<int>(plot.w / 90)));
  out += "<g class=\"grid\" stroke=\"#e6e6e6\" stroke-width=\"1\">\n";
  for (const double t : yticks)
    out += "<line x1=\"" + num(plot.x) + "\" y1=\"" + num(m.py(t)) + "\" x2=\"" + num(plot.right()) + "\" y2=\"" +
           num(m.py(t)) + "\"/>\n";
  for (const double t : xticks)
    out += "<line x1=\"" + num(m.px(t)) + "\" y1=\"" + num(plot.y) + "\" x2=\"" + num(m.px(t)) + "\" y2=\"" +
           num(plot.bottom()) + "\"/>\n";
  out += "</g>\n";
  out += "<g class=\"ticks\" stroke=\"#000000\" stroke-width=\"1\">\n";
  for (const double t : yticks)
    out += "<line x1=\"" + num(plot.x - 5) + "\" y1=\"" + num(m.py(t)) + "\" x2=\"" + num(plot.x) + "\" y2=\"" +
           num(m.py(t)) + "\"/>\n";
  for (const double t : xticks)
    out += "<line x1=\"" + num(m.px(t)) + "\" y1=\"" + num(plot.bottom()) + "\" x2=\"" + num(m.px(t)) + "\" y2=\"" +
           num(plot.bottom() + 5) + "\"/>\n";
  out += "</g>\n";
  for (const double t : yticks) text(out, plot.x - 8, m.py(t) + kFont * 0.35, tick_label(t, yticks), "end");
  if (x_labels)
    for (const double t : xticks) text(out, m.px(t), plot.bottom() + 8 + kFont, tick_label(t, xticks), "middle");
}

// Everything data-driven, clipped to the plot: gap bands, reference lines, then each series.
void draw_clipped_data(std::string& out, const Figure& f, const Mapper& m, int clip_id) {
  const Box& plot = m.plot;
  const std::string clip = "plot-clip-" + std::to_string(clip_id);
  out += "<defs><clipPath id=\"" + clip + "\"><rect x=\"" + num(plot.x) + "\" y=\"" + num(plot.y) + "\" width=\"" +
         num(plot.w) + "\" height=\"" + num(plot.h) + "\"/></clipPath></defs>\n";
  out += "<g clip-path=\"url(#" + clip + ")\">\n";
  for (const Series& s : f.series)
    if (s.shade_gaps) svg::gap_bands(out, s, m);
  for (const ReferenceLine& r : f.references) {
    if (!std::isfinite(r.y)) continue;
    out += "<line class=\"reference\" x1=\"" + num(plot.x) + "\" y1=\"" + num(m.py(r.y)) + "\" x2=\"" +
           num(plot.right()) + "\" y2=\"" + num(m.py(r.y)) + "\" stroke=\"" + hex(r.colour) + "\" stroke-width=\"1\"" +
           dash_attr(r.dash) + "/>\n";
  }
  for (size_t i = 0; i < f.series.size(); ++i) {
    const Series& s = f.series[i];
    const Rgb c = colour_of(s, i);
    if (s.style != SeriesStyle::points) svg::line_pieces(out, s, m, c);
    if (s.style != SeriesStyle::line) svg::points(out, s, m, c);
  }
  out += "</g>\n";
}

// Reference labels beside the plot at their line's height, nudged apart so none overlap.
void draw_reference_labels(std::string& out, const Figure& f, const Mapper& m) {
  const Box& plot = m.plot;
  std::vector<std::pair<double, const ReferenceLine*>> labels;
  for (const ReferenceLine& r : f.references)
    if (std::isfinite(r.y) && !r.label.empty() && r.y >= m.yr.lo && r.y <= m.yr.hi) labels.push_back({m.py(r.y), &r});
  std::stable_sort(labels.begin(), labels.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 1; i < labels.size(); ++i)
    labels[i].first = std::max(labels[i].first, labels[i - 1].first + kFont + 1);
  for (const auto& [y, r] : labels) text(out, plot.right() + 6, y + kFont * 0.35, r->label, "start");
}

// One chart inside `area`: its title (grid panels), legend above the plot, axes, the clipped
// curves and reference lines, reference labels to the right of the plot.
void panel(std::string& out, const Figure& f, Box area, const AxisRange& xr, const PanelStyle& st) {
  double top = area.y;
  if (st.own_title && !f.title.empty()) {
    text(out, area.x + st.left, top + kPanelFont, f.title, "start", kPanelFont, " font-weight=\"bold\"");
    top += kPanelFont + 8;
  }
  int rows = 0;
  const double plot_w = std::max(20.0, area.w - st.left - st.right);
  const auto legend = legend_layout(f, plot_w, rows);
  const double legend_top = top;
  top += rows * kLineHeight + (rows > 0 ? 4 : 0);
  const double bottom_room = st.x_labels ? (kFont + 10) + (st.x_axis_text.empty() ? 0 : kFont + 10) : 6;
  Box plot{area.x + st.left, top + 4, plot_w, std::max(20.0, area.bottom() - bottom_room - top - 4)};
  const Mapper m{xr, y_range(f), plot};

  // Legend: outside the plot, above it.
  for (const LegendItem& it : legend) {
    const Series& s = f.series[it.series];
    const double y = legend_top + it.row * kLineHeight + kLineHeight / 2;
    swatch(out, plot.x + it.x, y, s, colour_of(s, it.series));
    text(out, plot.x + it.x + 24, y + kFont * 0.35, s.name, "start");
  }

  draw_grid_and_ticks(out, m, st.x_labels);

  // Axis labels with units.
  const std::string ylabel = axis_text(f.y);
  if (!ylabel.empty()) {
    const double cx = area.x + 14, cy = plot.y + plot.h / 2;
    out += "<text x=\"0\" y=\"0\" transform=\"translate(" + num(cx) + "," + num(cy) +
           ") rotate(-90)\" text-anchor=\"middle\">" + xml_escape(ylabel) + "</text>\n";
  }
  if (st.x_labels && !st.x_axis_text.empty())
    text(out, plot.x + plot.w / 2, plot.bottom() + 2 * (kFont + 10) - 4, st.x_axis_text, "middle");

  draw_clipped_data(out, f, m, st.clip_id);
  out += "<rect class=\"frame\" x=\"" + num(plot.x) + "\" y=\"" + num(plot.y) + "\" width=\"" + num(plot.w) +
         "\" height=\"" + num(plot.h) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";

  draw_reference_labels(out, f, m);
}

// Notes under everything, one line each; returns the height they take.
double notes_height(const std::vector<std::string>& notes) {
  return notes.empty() ? 0 : notes.size() * kLineHeight + 4;
}

void write_notes(std::string& out, const std::vector<std::string>& notes, double left, double top) {
  for (size_t i = 0; i < notes.size(); ++i)
    text(out, left, top + static_cast<double>(i) * kLineHeight + kFont, notes[i], "start", kFont, " fill=\"#333333\"");
}

}  // namespace

std::string to_svg(const Figure& figure, int width_px, int height_px) {
  const int w = std::max(width_px, 240), h = std::max(height_px, 160);
  std::string out;
  document_start(out, w, h, figure.title);
  const double top = title_band(out, w, figure.title);
  const double notes = notes_height(figure.notes);
  PanelStyle st;
  st.left = left_margin(figure);
  st.right = std::min(right_margin(figure), w * 0.35);  // a long label must not squeeze the plot away
  st.x_axis_text = axis_text(figure.x);
  const Box area{0, top, static_cast<double>(w), h - top - notes - 4};
  panel(out, figure, area, x_range(figure), st);
  write_notes(out, figure.notes, st.left, h - notes);
  out += "</svg>\n";
  return out;
}

std::string to_svg(const FigureGrid& grid, int width_px, int height_px) {
  const int w = std::max(width_px, 240), h = std::max(height_px, 160);
  std::string out;
  document_start(out, w, h, grid.title);
  const double top = title_band(out, w, grid.title);
  const double notes = notes_height(grid.notes);
  PanelStyle st;
  for (const Figure& f : grid.panels) {
    st.left = std::max(st.left, left_margin(f));
    st.right = std::max(st.right, right_margin(f));
  }
  if (grid.panels.empty()) st.left = 40;
  st.right = std::min(st.right, w * 0.35);
  st.x_axis_text = axis_text(grid.x);
  st.own_title = true;
  const AxisRange xr = x_range(grid);
  // The bottom panel also holds the x tick labels and axis label: its area is taller by that much.
  const double x_room = (kFont + 10) + (st.x_axis_text.empty() ? 0 : kFont + 10) - 6;
  const double n = static_cast<double>(std::max<size_t>(1, grid.panels.size()));
  const double each = std::max(40.0, (h - top - notes - 4 - x_room) / n);
  for (size_t i = 0; i < grid.panels.size(); ++i) {
    st.x_labels = i + 1 == grid.panels.size();
    st.clip_id = static_cast<int>(i);
    const Box area{0, top + static_cast<double>(i) * each, static_cast<double>(w), each + (st.x_labels ? x_room : 0)};
    panel(out, grid.panels[i], area, xr, st);
  }
  write_notes(out, grid.notes, st.left, h - notes);
  out += "</svg>\n";
  return out;
}

}  // namespace lmc
