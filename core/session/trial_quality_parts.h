#pragma once
// The pieces assess_trial (trial_quality.h) is built from, each in its own file so each stays
// small and testable: per-controller stream statistics (trial_quality_devices.cpp) and the
// "at this instant, what did each controller last report" grid that hand presence, finger
// visibility and the range of motion are read from (trial_quality_grid.cpp). Internal to
// core/session; callers use trial_quality.h.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/hand/hand_track.h"
#include "core/io/lmc_recording.h"
#include "core/layout/layout.h"
#include "core/session/trial_quality.h"
#include "core/stats/percentile.h"

namespace lmc::trial_quality_detail {

// One controller's rows of the recording, sorted by device timestamp (the file interleaves
// controllers and USB delivery can swap neighbours).
struct DeviceRows {
  int device_id = 0;
  std::vector<const HandFrame*> rows;
};

// Every device id of the recording, ascending, each with its rows in time order.
std::vector<DeviceRows> rows_by_device(const LmcRecording& recording);

// A controller whose timestamps jump back by more than `limit_us` in file order: the tracking
// service restarted and reset its clock (resample.h's clock reset). Sorted by time such a stream
// interleaves two clocks, so every number drawn from it is wrong; the verdict says why instead.
struct ClockJump {
  int device_id = 0;
  std::int64_t back_us = 0;  // the largest backward jump
};
std::vector<ClockJump> clock_jumps(const LmcRecording& recording, std::int64_t limit_us);

// Frames, rates, hand fraction and gaps of one controller. The trial's first and last timestamps
// (over all controllers) bound it, so silence at either end counts as a gap: a controller
// unplugged mid-trial that never came back shows up here.
DeviceQuality device_stream_quality(const DeviceRows& device, std::int64_t trial_first_us, std::int64_t trial_last_us);

// Linear-interpolation percentile (numpy's default) of unsorted values; NaN when empty.

// Sample-and-hold grid: at each grid instant, for each controller, the index of its latest row
// at or before that instant, or −1 when it has none or that row is stale (older than the hold
// time: a controller that stopped sending is not assumed to still see what it last saw).
struct HeldGrid {
  std::int64_t start_us = 0;
  double step_us = 10000.0;
  int bins = 0;
  int devices = 0;
  std::vector<int> row;  // row[bin * devices + device]

  int held(int bin, int device) const {
    return row[static_cast<size_t>(bin) * static_cast<size_t>(devices) + static_cast<size_t>(device)];
  }
};

HeldGrid hold_on_grid(const std::vector<DeviceRows>& devices, std::int64_t first_us, std::int64_t last_us,
                      double step_us);

// One controller's rows as a track in its own frame, and the ray-traced labels of each row
// (core/processing/visibility_labels.h: the engine processing uses).
struct TracedDevice {
  int device_id = 0;
  HandTrack device_frame;
  std::vector<FingerLabels> labels;
};
TracedDevice trace_device(const DeviceRows& device);

// Share of grid instants at which some controller held a row with a hand, and per finger the
// share of those instants at which some controller's row saw it (label 1; NaN when the hand was
// never present).
struct Coverage {
  double hand_fraction = 0;
  std::array<double, kNumDigits> finger_seen{};
};
Coverage coverage(const HeldGrid& grid, const std::vector<TracedDevice>& devices);

// The grid cut into `slices` equal parts (fewer when the grid has fewer instants), each summed
// into QualityTimeline's series. `devices` is in the order of `grid`.
QualityTimeline timeline(const HeldGrid& grid, const std::vector<TracedDevice>& devices, int slices);

// The measures.h angle index of a protocol joint name ("Wrist", "Index_MCP", "index mcp" …;
// case, spaces and dashes ignored), or −1.
int angle_index(const std::string& joint);

// Range of motion (95th − 5th percentile, degrees) of angle `angle` of a cheap fusion: per grid
// instant the per-coordinate median of the held rows that have a hand, realigned with the layout
// (device id k is layout device k; a device the layout lacks is left out). NaN when the angle is
// never known. `devices` is in the order of `grid`.
double reached_rom_deg(const HeldGrid& grid, const std::vector<TracedDevice>& devices, const Layout& layout, int angle);

}  // namespace lmc::trial_quality_detail
