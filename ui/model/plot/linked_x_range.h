#pragma once
// One x range shared by several stacked plots: zooming, panning or resetting any of
// them moves all of them, and the cursor (the time a person points at) is shared too. A plot holds
// a shared_ptr to the same LinkedXRange; nothing here draws.
#include <optional>

namespace lmc::ui {

class LinkedXRange {
 public:
  // The data's extent: what reset() returns to. A view that showed the whole old extent shows the
  // whole new one; a zoomed or panned view keeps its place.
  void set_extent(double lo, double hi);
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double extent_lo() const { return extent_lo_; }
  double extent_hi() const { return extent_hi_; }

  // Zoom by `factor` (< 1 zooms in) keeping x = `about` where it is on screen. The view never gets
  // narrower than `min_width` nor wider than the extent, and stays inside the extent.
  void zoom(double about, double factor);
  void pan(double dx);  // shifts the view; clamped to the extent
  void reset();
  void set_min_width(double w) { min_width_ = w; }

  std::optional<double> cursor;  // shared hover position, in x units

 private:
  void clamp();
  double extent_lo_ = 0, extent_hi_ = 1, lo_ = 0, hi_ = 1, min_width_ = 1e-9;
  bool has_extent_ = false;
};

}  // namespace lmc::ui
