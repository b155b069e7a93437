#include "ui/model/record/subject_window_placement.h"

#include <algorithm>
#include <sstream>

namespace lmc::ui {
namespace {

long long overlap_area(const ScreenRect& a, const ScreenRect& b) {
  const long long w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
  const long long h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

constexpr int kMinWidth = 400;  // narrower, the subject's cue wraps word by word
constexpr int kMargin = 8;
constexpr int kTaskbar = 48;  // room for a desktop's panel along the monitor's bottom edge

// 16:10, as the subject screen's layout is drawn for.
ScreenRect sized(int x, int y, int width, int max_height) {
  const int height = std::min(max_height, width * 10 / 16);
  return {x, y, width, height};
}

}  // namespace

ScreenRect subject_window_rect(const std::vector<ScreenRect>& monitors, int monitor, const ScreenRect& operator_window,
                               const std::optional<ScreenRect>& remembered) {
  if (monitors.empty()) return remembered.value_or(ScreenRect{40, 40, 640, 400});
  if (remembered && remembered->width >= 200 && remembered->height >= 120) {
    const long long area = static_cast<long long>(remembered->width) * remembered->height;
    for (const auto& m : monitors)
      if (overlap_area(*remembered, m) * 10 >= area * 8) return *remembered;  // mostly on a monitor still
  }
  size_t chosen = 0;
  if (monitor >= 0 && monitor < static_cast<int>(monitors.size())) {
    chosen = static_cast<size_t>(monitor);
  } else {
    for (size_t i = 1; i < monitors.size(); ++i)
      if (overlap_area(operator_window, monitors[i]) > overlap_area(operator_window, monitors[chosen])) chosen = i;
  }
  const ScreenRect& m = monitors[chosen];
  const int usable_height = m.height - 2 * kMargin - kTaskbar;
  // Beside the workbench when it leaves a strip wide enough on either side.
  const int right = (m.x + m.width) - (operator_window.x + operator_window.width) - 2 * kMargin;
  const int left = operator_window.x - m.x - 2 * kMargin;
  if (overlap_area(operator_window, m) > 0 && std::max(left, right) >= kMinWidth) {
    const int width = std::min(std::max(left, right), 960);
    const int x = right >= left ? operator_window.x + operator_window.width + kMargin : m.x + kMargin + (left - width);
    return sized(x, m.y + kMargin, width, usable_height);
  }
  // The workbench fills the monitor: a third of it, bottom right.
  const int width = std::max(kMinWidth, m.width / 3);
  const ScreenRect r = sized(0, 0, width, usable_height);
  return {m.x + m.width - r.width - kMargin, m.y + m.height - r.height - kMargin - kTaskbar, r.width, r.height};
}

std::string subject_window_rect_text(const ScreenRect& r) {
  return std::to_string(r.x) + " " + std::to_string(r.y) + " " + std::to_string(r.width) + " " +
         std::to_string(r.height);
}

std::optional<ScreenRect> parse_subject_window_rect(const std::string& text) {
  std::istringstream in(text);
  ScreenRect r;
  if (!(in >> r.x >> r.y >> r.width >> r.height)) return std::nullopt;
  std::string rest;
  if (in >> rest) return std::nullopt;
  if (r.width <= 0 || r.height <= 0 || r.width > 100000 || r.height > 100000) return std::nullopt;
  return r;
}

}  // namespace lmc::ui
