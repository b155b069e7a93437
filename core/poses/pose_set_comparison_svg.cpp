// The comparison's figure (pose_set_comparison.h): a grid of small panels, one per quantity, each
// with both sets' histograms drawn as steps over the common range and the overlap in its title.
#include <algorithm>

#include "core/common/number_format.h"
#include "core/figures/locale_free_number.h"
#include "core/figures/palette.h"
#include "core/figures/svg_text.h"
#include "core/poses/pose_set_comparison.h"

namespace lmc {
namespace {

std::string colour_text(Rgb c) {
  return "rgb(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + ")";
}

// One histogram as a step line inside the panel box (x0, y0, w, h), shares scaled to `top`.
std::string step_path(const std::vector<double>& share, double top, double x0, double y0, double w, double h) {
  const double bin_w = w / static_cast<double>(std::max<size_t>(1, share.size()));
  std::string d = "M" + fixed_c(x0, 1) + "," + fixed_c(y0 + h, 1);
  for (size_t i = 0; i < share.size(); ++i) {
    const double y = y0 + h - h * share[i] / top;
    d += " L" + fixed_c(x0 + bin_w * static_cast<double>(i), 1) + "," + fixed_c(y, 1);
    d += " L" + fixed_c(x0 + bin_w * static_cast<double>(i + 1), 1) + "," + fixed_c(y, 1);
  }
  d += " L" + fixed_c(x0 + w, 1) + "," + fixed_c(y0 + h, 1);
  return d;
}

}  // namespace

std::string pose_set_comparison_svg(const PoseSetComparison& c, const std::string& a_label,
                                    const std::string& b_label) {
  namespace svg = svg;
  constexpr int kColumns = 3;
  constexpr double kPanelW = 300, kPanelH = 150, kGapX = 30, kGapY = 62, kMargin = 30;
  const int rows = (static_cast<int>(c.quantities.size()) + kColumns - 1) / kColumns;
  const int width = static_cast<int>(2 * kMargin + kColumns * kPanelW + (kColumns - 1) * kGapX);
  const double legend_h = 2 * svg::kLineHeight + 8;
  const std::string title = "Pose sets compared: " + a_label + " against " + b_label;
  const int height = static_cast<int>(60 + legend_h + rows * (kPanelH + kGapY) + 3 * svg::kLineHeight);
  std::string out;
  svg::document_start(out, width, height, title);
  double top = svg::title_band(out, width, title);
  const Rgb ca = series_colour(4), cb = series_colour(0);
  const std::string hands = "hands the other set never has (palm in 30 mm cubes x tilt in 30° steps): " + a_label +
                            " " + format_fixed(100.0 * c.a_hands_b_never_has, 1) + " % of its frames, " + b_label +
                            " " + format_fixed(100.0 * c.b_hands_a_never_has, 1) + " %";
  out += "<rect x=\"" + fixed_c(kMargin, 1) + "\" y=\"" + fixed_c(top + 4, 1) + "\" width=\"18\" height=\"4\" fill=\"" +
         colour_text(ca) + "\"/>";
  svg::text(out, kMargin + 24, top + 10, a_label + " (" + std::to_string(c.a_frames) + " frames)", "start");
  out += "<rect x=\"" + fixed_c(kMargin + width / 2.0, 1) + "\" y=\"" + fixed_c(top + 4, 1) +
         "\" width=\"18\" height=\"4\" fill=\"" + colour_text(cb) + "\"/>";
  svg::text(out, kMargin + width / 2.0 + 24, top + 10, b_label + " (" + std::to_string(c.b_frames) + " frames)",
            "start");
  svg::text(out, kMargin, top + 10 + svg::kLineHeight, hands, "start");
  top += legend_h + 20;
  for (size_t q = 0; q < c.quantities.size(); ++q) {
    const QuantityComparison& k = c.quantities[q];
    const double x0 = kMargin + static_cast<double>(q % kColumns) * (kPanelW + kGapX);
    const double y0 = top + static_cast<double>(q / kColumns) * (kPanelH + kGapY);
    double peak = 1e-9;
    for (const double v : k.a_share) peak = std::max(peak, v);
    for (const double v : k.b_share) peak = std::max(peak, v);
    svg::text(out, x0, y0 - 6, k.name + ": overlap " + format_fixed(100.0 * k.overlap, 0) + " %", "start", svg::kFont,
              " font-weight=\"bold\"");
    out += "<rect x=\"" + fixed_c(x0, 1) + "\" y=\"" + fixed_c(y0, 1) + "\" width=\"" + fixed_c(kPanelW, 1) +
           "\" height=\"" + fixed_c(kPanelH, 1) + "\" fill=\"none\" stroke=\"#bbbbbb\"/>";
    out += "<path d=\"" + step_path(k.b_share, peak, x0, y0, kPanelW, kPanelH) + "\" fill=\"" + colour_text(cb) +
           "\" fill-opacity=\"0.35\" stroke=\"" + colour_text(cb) + "\" stroke-width=\"1.2\"/>";
    out += "<path d=\"" + step_path(k.a_share, peak, x0, y0, kPanelW, kPanelH) + "\" fill=\"none\" stroke=\"" +
           colour_text(ca) + "\" stroke-width=\"1.8\"/>";
    svg::text(out, x0, y0 + kPanelH + 14, format_fixed(k.lo, 0) + " " + k.unit, "start");
    svg::text(out, x0 + kPanelW, y0 + kPanelH + 14, format_fixed(k.hi, 0) + " " + k.unit, "end");
  }
  svg::text(out, kMargin, height - 2 * svg::kLineHeight + 4,
            "Each panel: the share of each set's frames per bin over both sets' common range (40 bins); overlap = "
            "sum of the smaller share in every bin.",
            "start");
  svg::text(out, kMargin, height - svg::kLineHeight + 4,
            "Palm axes from the points (core/hand/palm_axes.h); joint angles as the study measures them.", "start");
  out += "</svg>\n";
  return out;
}

}  // namespace lmc
