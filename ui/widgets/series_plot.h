#pragma once
// A plot worth reusing (ImPlot is not in Debian 12): several series against one x, the
// y axis fitted to what is visible, wheel zoom, drag pan and double-click reset on an x range that
// several plots can share (ui/model/plot/linked_x_range.h), a cursor line with every series' value
// at it, NaN drawn as gaps over a faint band, a legend strip above the curves whose entries toggle
// their series, round ticks with axis labels and units, and the colour-blind-safe palette. All the
// arithmetic (decimation, ticks, ranges) is in ui/model/plot and tested headless; this draws.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ui/model/plot/linked_x_range.h"

namespace lmc::ui {

// Left of the plot area: the y tick labels. Widgets drawn under a plot on the same x range (the
// Review tab's label strips) start their x axis here too, so times line up.
inline constexpr float kSeriesPlotGutterPx = 48.0F;

struct PlotSeries {
  std::string name;              // legend text and the key of its on/off state
  std::span<const double> x, y;  // x ascending, same length
  int colour = -1;               // palette index; −1: the series' position
};

struct SeriesPlotOptions {
  float height_px = 150;
  std::string y_label;  // with its unit, e.g. "angle (deg)"
  std::string x_label;  // e.g. "time (s)"; empty: no x tick labels (a plot above others sharing x)
  bool log_y = false;   // log10 of positive values (a convergence curve); others become gaps
};

class SeriesPlot {
 public:
  explicit SeriesPlot(std::shared_ptr<LinkedXRange> x_range = std::make_shared<LinkedXRange>())
      : x_(std::move(x_range)) {}
  // Draws at the cursor, full available width. Series hidden with the legend stay hidden by name.
  void draw(const char* id, const std::vector<PlotSeries>& series, const SeriesPlotOptions& options);
  const std::shared_ptr<LinkedXRange>& x_range() const { return x_; }
  bool hidden(const std::string& name) const;

 private:
  void draw_legend(const std::vector<PlotSeries>& series, const SeriesPlotOptions& options);
  // On the plot's invisible button, just drawn: `plot_left` and `plot_w` in screen pixels.
  void handle_input(float plot_left, float plot_w);

  std::shared_ptr<LinkedXRange> x_;
  std::map<std::string, bool> hidden_;
};

}  // namespace lmc::ui
