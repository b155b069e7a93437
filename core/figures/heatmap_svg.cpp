#include "core/figures/heatmap_svg.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "core/common/xml_text.h"
#include "core/figures/colour_scale.h"
#include "core/figures/locale_free_number.h"
#include "core/figures/svg_marks.h"
#include "core/figures/svg_text.h"

namespace lmc {
namespace heatmap_svg {  // named: core compiles in unity batches beside svg_writer.cpp

using svg::hex;
using svg::kFont;
using svg::kLineHeight;
using svg::kPanelFont;
using svg::num;
using svg::text;
using svg::text_width;

constexpr double kPad = 8;        // between labels and what they label
constexpr double kPanelGap = 12;  // between stacked panels
constexpr double kBarWidth = 16;  // the legend's colour bar
constexpr double kSwatch = 14;    // the legend's "no data" sample
constexpr const char* kHatchId = "heatmap-no-data";
constexpr const char* kGradientId = "heatmap-scale";
constexpr Rgb kCellBorder{255, 255, 255};

// <text class="…" …>: the class first, so a reader can pick the element out by its opening.
void classed_text(std::string& out, std::string_view cls, double x, double y, std::string_view s,
                  std::string_view anchor, std::string_view extra = {}) {
  out += "<text class=\"" + std::string(cls) + "\" x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" +
         std::string(anchor) + "\"" + std::string(extra) + ">" + xml_escape(s) + "</text>\n";
}

std::string value_text(double v, HeatmapValueText how) {
  switch (how) {
    case HeatmapValueText::percent:
      return fixed_c(100.0 * v, 0) + " %";
    case HeatmapValueText::fraction:
      return fixed_c(v, 2);
    case HeatmapValueText::none:
      break;
  }
  return {};
}

// The legend's tick text: percent when the cells say percent, else the fraction.
std::string tick_text(double v, HeatmapValueText how) {
  return how == HeatmapValueText::percent ? value_text(v, how) : fixed_c(v, 2);
}

// Column labels either wrapped onto lines under their cell, or (when a single word is wider than
// a cell) turned to read upwards, one line each.
struct ColumnLabels {
  bool upright = false;
  std::vector<std::vector<std::string>> lines;  // per column
  double height = 0;                            // the band they take under the cells
};

ColumnLabels lay_out_columns(const Heatmap& h, double cell_w) {
  ColumnLabels c;
  size_t most = 0;
  double longest = 0;
  for (const std::string& label : h.columns) {
    c.lines.push_back(svg::wrap_words(label, cell_w - 4));
    most = std::max(most, c.lines.back().size());
    longest = std::max(longest, text_width(label));
    for (const std::string& line : c.lines.back())
      if (text_width(line) > cell_w - 4) c.upright = true;
  }
  if (c.upright) {
    for (size_t i = 0; i < h.columns.size(); ++i) c.lines[i] = {h.columns[i]};
    c.height = longest + kPad;
  } else {
    c.height = static_cast<double>(most) * (kFont + 3) + kPad;
  }
  return c;
}

bool has_groups(const Heatmap& h) {
  return !h.column_groups.empty() && h.column_groups.size() == h.columns.size();
}

// Runs of consecutive columns in one group: [first, last] and the name.
struct GroupRun {
  size_t first, last;
  std::string name;
};

std::vector<GroupRun> group_runs(const Heatmap& h) {
  std::vector<GroupRun> runs;
  if (!has_groups(h)) return runs;
  for (size_t i = 0; i < h.columns.size(); ++i) {
    if (!runs.empty() && runs.back().name == h.column_groups[i])
      runs.back().last = i;
    else
      runs.push_back({i, i, h.column_groups[i]});
  }
  return runs;
}

void defs(std::string& out) {
  out += "<defs>\n";
  out += "<pattern id=\"" + std::string(kHatchId) +
         "\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" "
         "patternTransform=\"rotate(45)\"><rect x=\"0\" y=\"0\" width=\"6\" height=\"6\" "
         "fill=\"#e3e3e3\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#9a9a9a\" "
         "stroke-width=\"2\"/></pattern>\n";
  // Bottom (0) to top (1), at the scale's own control points so the bar matches the cells.
  out += "<linearGradient id=\"" + std::string(kGradientId) + "\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n";
  for (int i = 0; i <= 8; ++i) {
    const double t = i / 8.0;
    out += "<stop offset=\"" + num(t) + "\" stop-color=\"" + hex(sequential_colour(t)) + "\"/>\n";
  }
  out += "</linearGradient>\n</defs>\n";
}

struct Legend {
  std::vector<std::string> label_lines;  // the scale label, wrapped along the bar
  double width = 0;
};

Legend lay_out_legend(const Heatmap& h, double bar_height) {
  Legend l;
  double ticks = 0;
  for (const double t : {0.0, 1.0}) ticks = std::max(ticks, text_width(tick_text(t, h.value_text)));
  l.width = kPad + kBarWidth + 6 + ticks;
  if (!h.scale_label.empty()) {
    l.label_lines = svg::wrap_words(h.scale_label, std::max(40.0, 0.95 * bar_height));
    l.width += kPad + static_cast<double>(l.label_lines.size()) * (kFont + 4);
  }
  if (h.has_missing()) l.width = std::max(l.width, kPad + kSwatch + 6 + text_width("no data"));
  return l.width > 0 ? l : Legend{};
}

void legend(std::string& out, const Heatmap& h, const Legend& l, double x, double top, double bottom) {
  const double bar_h = bottom - top;
  out += "<rect class=\"legend-bar\" x=\"" + num(x) + "\" y=\"" + num(top) + "\" width=\"" + num(kBarWidth) +
         "\" height=\"" + num(bar_h) + "\" fill=\"url(#" + kGradientId +
         ")\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  double right = x + kBarWidth;
  double widest = 0;
  for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double y = bottom - t * bar_h;
    out += "<line x1=\"" + num(x + kBarWidth) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x + kBarWidth + 4) + "\" y2=\"" +
           num(y) + "\" stroke=\"#000000\"/>\n";
    const std::string s = tick_text(t, h.value_text);
    widest = std::max(widest, text_width(s));
    text(out, x + kBarWidth + 6, y + kFont * 0.35, s, "start");
  }
  right += 6 + widest;
  // The scale label reads upwards beside the ticks, its lines side by side.
  for (size_t i = 0; i < l.label_lines.size(); ++i) {
    const double cx = right + kPad + kFont * 0.8 + static_cast<double>(i) * (kFont + 4);
    const double cy = top + bar_h / 2;
    out += "<text class=\"scale-label\" x=\"0\" y=\"0\" transform=\"translate(" + num(cx) + "," + num(cy) +
           ") rotate(-90)\" text-anchor=\"middle\">" + xml_escape(l.label_lines[i]) + "</text>\n";
  }
  if (h.has_missing()) {
    const double y = bottom + kPad + 4;
    out += "<rect class=\"legend-no-data\" x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(kSwatch) +
           "\" height=\"" + num(kSwatch) + "\" fill=\"url(#" + kHatchId +
           ")\" stroke=\"#9a9a9a\" stroke-width=\"1\"/>\n";
    text(out, x + kSwatch + 6, y + kSwatch / 2 + kFont * 0.35, "no data", "start");
  }
}

// Where everything goes. The legend's width depends on the bar's height (its label wraps along
// the bar), the cells' width on the legend and the column-label band's height on the cells'
// width: lay_out() is run twice, the second time with the bar height the first one found.
struct Geometry {
  double top = 0;  // under the title
  double cells_x = 0, cells_w = 0, cell_w = 0, cell_h = 0;
  double panel_title_h = 0, groups_h = 0, column_title_h = 0, notes_h = 0;
  double bar_h = 0;  // from the first panel's cells to the last one's
  Legend legend;
  ColumnLabels labels;
};

Geometry lay_out(const Heatmap& h, int w, int hgt, double top, double bar_guess) {
  Geometry g;
  g.top = top;
  const double rows = static_cast<double>(std::max<size_t>(1, h.rows.size()));
  const double cols = static_cast<double>(std::max<size_t>(1, h.columns.size()));
  const double panels = static_cast<double>(std::max<size_t>(1, h.panels.size()));
  double row_labels = 0;
  for (const std::string& r : h.rows) row_labels = std::max(row_labels, text_width(r));
  const double row_title = h.row_title.empty() ? 0 : kFont + 10;
  g.cells_x = 10 + row_title + row_labels + kPad;
  g.legend = lay_out_legend(h, bar_guess);
  g.cells_w = std::max(20.0, w - g.cells_x - 16 - g.legend.width - 10);
  g.cell_w = g.cells_w / cols;

  g.labels = lay_out_columns(h, g.cell_w);
  g.groups_h = has_groups(h) ? kFont + 16 : 0;
  g.column_title_h = h.column_title.empty() ? 0 : kFont + 8;
  g.notes_h = h.notes.empty() ? 0 : static_cast<double>(h.notes.size()) * kLineHeight + 4;
  bool titled = false;
  for (const HeatmapPanel& p : h.panels) titled = titled || !p.title.empty();
  g.panel_title_h = titled ? kPanelFont + 8 : 0;
  // The "no data" swatch sits under the bar, beside the column labels: keep room for it.
  const double below =
      std::max(g.labels.height + g.groups_h + g.column_title_h, h.has_missing() ? kPad + 4 + kSwatch + 4 : 0.0);
  const double cells_total =
      std::max(20.0, hgt - top - below - g.notes_h - 8 - panels * g.panel_title_h - (panels - 1) * kPanelGap);
  g.cell_h = cells_total / (panels * rows);
  g.bar_h = cells_total + (panels - 1) * (g.panel_title_h + kPanelGap);
  return g;
}

// Panel p's cells from `y` down, each with its value when it fits, and the lines between groups.
void draw_panel_cells(std::string& out, const Heatmap& h, const Geometry& geo, size_t p, double y,
                      const std::vector<GroupRun>& runs) {
  const double cells_x = geo.cells_x, cell_w = geo.cell_w, cell_h = geo.cell_h;
  const size_t rows = std::max<size_t>(1, h.rows.size());
  out += "<g class=\"panel\">\n";
  for (size_t r = 0; r < h.rows.size(); ++r) {
    const double cy = y + static_cast<double>(r) * cell_h;
    classed_text(out, "row-label", cells_x - kPad, cy + cell_h / 2 + kFont * 0.35, h.rows[r], "end");
    for (size_t c = 0; c < h.columns.size(); ++c) {
      const double cx = cells_x + static_cast<double>(c) * cell_w;
      const double v = h.at(p, r, c);
      const bool missing = std::isnan(v);
      const Rgb fill = sequential_colour(missing ? 0.0 : v);
      out += "<rect class=\"" + std::string(missing ? "cell no-data" : "cell") + "\" x=\"" + num(cx) + "\" y=\"" +
             num(cy) + "\" width=\"" + num(cell_w) + "\" height=\"" + num(cell_h) + "\" fill=\"" +
             (missing ? "url(#" + std::string(kHatchId) + ")" : hex(fill)) + "\" stroke=\"" + hex(kCellBorder) +
             "\" stroke-width=\"1\"/>\n";
      const std::string s = missing ? std::string() : value_text(v, h.value_text);
      if (!s.empty() && text_width(s) <= cell_w - 4 && cell_h >= kFont + 2)
        classed_text(out, "cell-value", cx + cell_w / 2, cy + cell_h / 2 + kFont * 0.35, s, "middle",
                     std::string(" fill=\"") + (wants_light_text(fill) ? "#ffffff" : "#000000") + "\"");
    }
  }
  // A dark line between column groups, so "palm down" and "palm left" read as two blocks.
  for (size_t g = 1; g < runs.size(); ++g) {
    const double gx = cells_x + static_cast<double>(runs[g].first) * cell_w;
    out += "<line class=\"group-separator\" x1=\"" + num(gx) + "\" y1=\"" + num(y) + "\" x2=\"" + num(gx) + "\" y2=\"" +
           num(y + static_cast<double>(rows) * cell_h) + "\" stroke=\"#000000\" stroke-width=\"2\"/>\n";
  }
  out += "</g>\n";
}

// The column labels under the bottom panel from `y` down, then a bracket under each run of
// columns with its name; returns the y under them.
double draw_column_labels(std::string& out, const Heatmap& h, const Geometry& geo, const std::vector<GroupRun>& runs,
                          double y) {
  const double cells_x = geo.cells_x, cell_w = geo.cell_w;
  for (size_t c = 0; c < h.columns.size(); ++c) {
    const double cx = cells_x + (static_cast<double>(c) + 0.5) * cell_w;
    if (geo.labels.upright) {
      out += "<text class=\"column-label\" x=\"0\" y=\"0\" transform=\"translate(" + num(cx + kFont * 0.35) + "," +
             num(y) + ") rotate(-90)\" text-anchor=\"end\">" + xml_escape(h.columns[c]) + "</text>\n";
    } else {
      const auto& lines = geo.labels.lines[c];
      for (size_t i = 0; i < lines.size(); ++i)
        classed_text(out, "column-label", cx, y + kFont + static_cast<double>(i) * (kFont + 3), lines[i], "middle");
    }
  }
  y += geo.labels.height + 4;
  for (const GroupRun& g : runs) {
    const double x0 = cells_x + static_cast<double>(g.first) * cell_w + 4;
    const double x1 = cells_x + static_cast<double>(g.last + 1) * cell_w - 4;
    out += "<path class=\"group-bracket\" d=\"M" + num(x0) + "," + num(y - 4) + " L" + num(x0) + "," + num(y) + " L" +
           num(x1) + "," + num(y) + " L" + num(x1) + "," + num(y - 4) +
           "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    classed_text(out, "column-group", (x0 + x1) / 2, y + kFont + 3, g.name, "middle", " font-weight=\"bold\"");
  }
  return y + geo.groups_h;
}

}  // namespace heatmap_svg

std::string to_svg(const Heatmap& h, int width_px, int height_px) {
  using namespace heatmap_svg;
  const int w = std::max(width_px, 240), hgt = std::max(height_px, 160);
  const size_t rows = std::max<size_t>(1, h.rows.size());
  const size_t panels = std::max<size_t>(1, h.panels.size());

  std::string out;
  svg::document_start(out, w, hgt, h.title);
  defs(out);
  const double top = svg::title_band(out, w, h.title);
  const Geometry first = lay_out(h, w, hgt, top, 0.6 * hgt);
  const Geometry geo = lay_out(h, w, hgt, top, first.bar_h);
  const double cells_x = geo.cells_x, cells_w = geo.cells_w, cell_h = geo.cell_h;
  const auto runs = group_runs(h);
  const bool titled = geo.panel_title_h > 0;

  double y = top;
  double first_cells_top = 0, last_cells_bottom = 0;
  for (size_t p = 0; p < panels; ++p) {
    const std::string ptitle = p < h.panels.size() ? h.panels[p].title : std::string();
    if (titled) {
      text(out, cells_x, y + kPanelFont, ptitle, "start", kPanelFont, " font-weight=\"bold\"");
      y += geo.panel_title_h;
    }
    if (p == 0) first_cells_top = y;
    draw_panel_cells(out, h, geo, p, y, runs);
    y += static_cast<double>(rows) * cell_h;
    last_cells_bottom = y;
    if (p + 1 < panels) y += kPanelGap;
  }

  y = draw_column_labels(out, h, geo, runs, last_cells_bottom + kPad);
  if (!h.column_title.empty()) {
    text(out, cells_x + cells_w / 2, y + kFont + 2, h.column_title, "middle");
    y += geo.column_title_h;
  }
  if (!h.row_title.empty()) {
    const double cx = 10 + kFont, cy = (first_cells_top + last_cells_bottom) / 2;
    out += "<text x=\"0\" y=\"0\" transform=\"translate(" + num(cx) + "," + num(cy) +
           ") rotate(-90)\" text-anchor=\"middle\">" + xml_escape(h.row_title) + "</text>\n";
  }

  legend(out, h, geo.legend, cells_x + cells_w + 16, first_cells_top, last_cells_bottom);

  for (size_t i = 0; i < h.notes.size(); ++i)
    text(out, 10, hgt - geo.notes_h + static_cast<double>(i) * kLineHeight + kFont, h.notes[i], "start", kFont,
         " fill=\"#333333\"");
  out += "</svg>\n";
  return out;
}

}  // namespace lmc
