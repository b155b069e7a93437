// The sample-and-hold grid behind hand presence, finger visibility and range of motion
// (trial_quality_parts.h). Why not the processing resampler: its cubic splines are the right
// tool for measures, but a verdict seconds after the trial only needs "what did each controller
// last report at this instant", which is exact (no interpolated hand where none was reported) and
// costs a pointer walk. The ray tracer and realignment are processing's own.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/processing/measures.h"
#include "core/processing/realign.h"
#include "core/processing/visibility_labels.h"
#include "core/session/trial_quality_parts.h"

namespace lmc::trial_quality_detail {

namespace {

// A held row stays valid this many of the controller's typical frame intervals: with four
// controllers on one bus each streams at 11–34 Hz, so one late frame is rhythm, not loss (the
// same reasoning and factor as the resampler's adaptive gap limit, resample.h).
constexpr double kHoldIntervals = 2.5;

double median_interval_us(const DeviceRows& device) {
  std::vector<double> dts;
  dts.reserve(device.rows.size());
  for (size_t i = 1; i < device.rows.size(); ++i) {
    const std::int64_t dt = device.rows[i]->timestamp_us - device.rows[i - 1]->timestamp_us;
    if (dt > 0) dts.push_back(static_cast<double>(dt));
  }
  return dts.empty() ? 0.0 : percentile(std::move(dts), 50);
}

std::string squeeze(const std::string& name) {
  std::string out;
  for (const char c : name) {
    if (c == ' ' || c == '_' || c == '-') continue;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

// Median of a few values (at most kMaxDevices), in place. An insertion sort: for eight values it is
// as fast as std::sort, and GCC's bounds analysis cannot follow std::sort's introsort into a fixed
// array (a false -Warray-bounds in Release builds).
double small_median(double* v, int n) {
  for (int i = 1; i < n; ++i) {
    const double x = v[i];
    int j = i - 1;
    for (; j >= 0 && v[j] > x; --j) v[j + 1] = v[j];
    v[j + 1] = x;
  }
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

HeldGrid hold_on_grid(const std::vector<DeviceRows>& devices, std::int64_t first_us, std::int64_t last_us,
                      double step_us) {
  HeldGrid grid;
  grid.start_us = first_us;
  grid.step_us = step_us;
  grid.devices = static_cast<int>(devices.size());
  grid.bins =
      last_us >= first_us ? static_cast<int>(std::floor(static_cast<double>(last_us - first_us) / step_us)) + 1 : 0;
  grid.row.assign(static_cast<size_t>(grid.bins) * devices.size(), -1);
  for (size_t d = 0; d < devices.size(); ++d) {
    const auto& rows = devices[d].rows;
    const double hold_us = std::max(step_us, kHoldIntervals * median_interval_us(devices[d]));
    size_t next = 0;  // first row after the current instant
    for (int b = 0; b < grid.bins; ++b) {
      const double t = static_cast<double>(first_us) + b * step_us;
      while (next < rows.size() && static_cast<double>(rows[next]->timestamp_us) <= t) ++next;
      if (next == 0) continue;
      if (t - static_cast<double>(rows[next - 1]->timestamp_us) > hold_us) continue;
      grid.row[static_cast<size_t>(b) * devices.size() + d] = static_cast<int>(next - 1);
    }
  }
  return grid;
}

TracedDevice trace_device(const DeviceRows& device) {
  TracedDevice out;
  out.device_id = device.device_id;
  out.device_frame = HandTrack(static_cast<int>(device.rows.size()));
  for (int f = 0; f < out.device_frame.frame_count; ++f) {
    const HandFrame& row = *device.rows[static_cast<size_t>(f)];
    if (!row.hand_present) continue;  // the track's NaN frame means "no hand"
    for (int i = 0; i < kNumHandPoints; ++i) out.device_frame.at(f, i) = row.point(i);
  }
  out.labels = visibility_labels(out.device_frame);
  return out;
}

Coverage coverage(const HeldGrid& grid, const std::vector<TracedDevice>& devices) {
  Coverage c;
  int hand_bins = 0;
  std::array<int, kNumDigits> seen{};
  for (int b = 0; b < grid.bins; ++b) {
    bool hand = false;
    std::array<bool, kNumDigits> seen_here{};
    for (int d = 0; d < grid.devices; ++d) {
      const int r = grid.held(b, d);
      if (r < 0) continue;
      const FingerLabels& labels = devices[static_cast<size_t>(d)].labels[static_cast<size_t>(r)];
      if (labels[0] < 0) continue;  // −1: this controller had no hand in that row
      hand = true;
      for (size_t k = 0; k < kNumDigits; ++k) seen_here[k] = seen_here[k] || labels[k] == 1;
    }
    if (!hand) continue;
    ++hand_bins;
    for (size_t k = 0; k < kNumDigits; ++k) seen[k] += seen_here[k] ? 1 : 0;
  }
  c.hand_fraction = grid.bins > 0 ? static_cast<double>(hand_bins) / grid.bins : 0.0;
  for (size_t k = 0; k < kNumDigits; ++k) {
    c.finger_seen[k] = hand_bins > 0 ? static_cast<double>(seen[k]) / hand_bins : kNaN;
  }
  return c;
}

int angle_index(const std::string& joint) {
  const std::string want = squeeze(joint);
  for (int a = 0; a < kNumAngles; ++a) {
    if (squeeze(std::string(angle_name(a))) == want) return a;
  }
  return -1;
}

double reached_rom_deg(const HeldGrid& grid, const std::vector<TracedDevice>& devices, const Layout& layout,
                       int angle) {
  // Each controller's rows into the world frame with its layout pose and offset, as processing
  // does before fusing.
  std::vector<HandTrack> world(devices.size());
  std::vector<bool> usable(devices.size(), false);
  for (size_t d = 0; d < devices.size(); ++d) {
    const int id = devices[d].device_id;
    if (id < 1 || id > layout.device_count()) continue;
    world[d] = devices[d].device_frame;
    realign_track(world[d], layout.devices[static_cast<size_t>(id - 1)]);
    usable[d] = true;
  }

  // The per-coordinate median across the controllers holding a hand: with three or four
  // controllers one internal-model guess cannot pull it far, and it costs nothing next to the
  // default Kalman smoother. With two it is their mean, with one that controller's value.
  HandTrack fused(grid.bins);
  std::vector<int> rows(static_cast<size_t>(grid.devices));
  std::vector<size_t> holders;
  double values[kMaxDevices];
  for (int b = 0; b < grid.bins; ++b) {
    holders.clear();
    for (int d = 0; d < grid.devices; ++d) {
      const int r = grid.held(b, d);
      if (r < 0 || !usable[static_cast<size_t>(d)] || !world[static_cast<size_t>(d)].has_hand(r)) continue;
      holders.push_back(static_cast<size_t>(d));
      rows[static_cast<size_t>(d)] = r;
    }
    if (holders.empty() || holders.size() > static_cast<size_t>(kMaxDevices)) continue;
    const int n = static_cast<int>(holders.size());
    for (int i = 0; i < kNumHandPoints; ++i) {
      for (int c = 0; c < 3; ++c) {
        for (int h = 0; h < n; ++h) {
          const size_t d = holders[static_cast<size_t>(h)];
          values[h] = world[d].at(rows[d], i)[c];
        }
        fused.at(b, i)[c] = small_median(values, n);
      }
    }
  }

  std::vector<double> angles;
  angles.reserve(static_cast<size_t>(grid.bins));
  for (int b = 0; b < grid.bins; ++b) {
    if (!fused.has_hand(b)) continue;
    const double a = measure_frame(fused, b).angle_deg[static_cast<size_t>(angle)];
    if (std::isfinite(a)) angles.push_back(a);
  }
  if (angles.empty()) return kNaN;
  return percentile(angles, 95) - percentile(angles, 5);
}

}  // namespace lmc::trial_quality_detail
