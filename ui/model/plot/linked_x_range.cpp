#include "ui/model/plot/linked_x_range.h"

#include <algorithm>

namespace lmc::ui {

void LinkedXRange::set_extent(double lo, double hi) {
  if (!(hi > lo)) hi = lo + 1.0;  // one sample or none: a unit range rather than a division by zero
  // A view showing all the data keeps showing all of it as the data grow (a live convergence
  // curve); a zoomed or panned view keeps its place.
  const bool following = !has_extent_ || (lo_ == extent_lo_ && hi_ == extent_hi_);
  extent_lo_ = lo;
  extent_hi_ = hi;
  has_extent_ = true;
  if (following) {
    lo_ = lo;
    hi_ = hi;
  }
  clamp();
}

void LinkedXRange::zoom(double about, double factor) {
  if (!(factor > 0)) return;
  const double width = std::clamp((hi_ - lo_) * factor, min_width_, extent_hi_ - extent_lo_);
  const double t = hi_ > lo_ ? std::clamp((about - lo_) / (hi_ - lo_), 0.0, 1.0) : 0.5;
  lo_ = about - t * width;
  hi_ = lo_ + width;
  clamp();
}

void LinkedXRange::pan(double dx) {
  lo_ += dx;
  hi_ += dx;
  clamp();
}

void LinkedXRange::reset() {
  lo_ = extent_lo_;
  hi_ = extent_hi_;
}

void LinkedXRange::clamp() {
  const double width = std::min(hi_ - lo_, extent_hi_ - extent_lo_);
  if (lo_ < extent_lo_) lo_ = extent_lo_;
  if (lo_ + width > extent_hi_) lo_ = extent_hi_ - width;
  hi_ = lo_ + width;
}

}  // namespace lmc::ui
