// Per-controller stream statistics for the quality verdict (trial_quality_parts.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/session/trial_quality_parts.h"
#include "core/stats/stream_rates.h"

namespace lmc::trial_quality_detail {

std::vector<DeviceRows> rows_by_device(const LmcRecording& recording) {
  std::map<int, std::vector<const HandFrame*>> by_id;
  for (const HandFrame& row : recording.rows) by_id[row.device_id].push_back(&row);
  std::vector<DeviceRows> out;
  out.reserve(by_id.size());
  for (auto& [id, rows] : by_id) {
    // Stable: rows with equal timestamps (duplicates) keep their file order.
    std::stable_sort(rows.begin(), rows.end(),
                     [](const HandFrame* a, const HandFrame* b) { return a->timestamp_us < b->timestamp_us; });
    out.push_back(DeviceRows{id, std::move(rows)});
  }
  return out;
}

std::vector<ClockJump> clock_jumps(const LmcRecording& recording, std::int64_t limit_us) {
  std::map<int, std::int64_t> last_us, worst_us;
  for (const HandFrame& row : recording.rows) {
    const auto [it, first] = last_us.try_emplace(row.device_id, row.timestamp_us);
    if (!first) {
      const std::int64_t back = it->second - row.timestamp_us;
      if (back > limit_us) worst_us[row.device_id] = std::max(worst_us[row.device_id], back);
      it->second = row.timestamp_us;
    }
  }
  std::vector<ClockJump> out;
  for (const auto& [id, back] : worst_us) out.push_back(ClockJump{id, back});
  return out;
}

namespace {

double seconds(std::int64_t us) {
  return static_cast<double>(us) * 1e-6;
}

}  // namespace

DeviceQuality device_stream_quality(const DeviceRows& device, std::int64_t trial_first_us, std::int64_t trial_last_us) {
  DeviceQuality q;
  q.device_id = device.device_id;
  q.frames = static_cast<std::int64_t>(device.rows.size());
  if (device.rows.empty()) {
    q.longest_gap_s = q.longest_no_hand_s = seconds(trial_last_us - trial_first_us);
    return q;
  }

  // Rates from consecutive timestamps (a duplicate row still counts as a frame).
  std::vector<std::int64_t> stamps_us;
  stamps_us.reserve(device.rows.size());
  for (const HandFrame* row : device.rows) stamps_us.push_back(row->timestamp_us);
  std::int64_t longest_gap_us = std::max(stamps_us.front() - trial_first_us, trial_last_us - stamps_us.back());
  for (size_t i = 1; i < stamps_us.size(); ++i)
    longest_gap_us = std::max(longest_gap_us, stamps_us[i] - stamps_us[i - 1]);
  q.longest_gap_s = seconds(longest_gap_us);
  if (const StreamRates rates = stream_rates(stamps_us); rates.intervals > 0) {
    q.median_rate_hz = rates.median_hz;
    q.rate_p5_hz = rates.p5_hz;
    q.rate_p95_hz = rates.p95_hz;
  }

  // Hand: the share of this controller's frames with a hand, and the longest run of frames
  // without one, timed from the last frame with a hand before the run (or the trial's start) to
  // the first after it (or the trial's end). Silence with no frame at all is a gap, not a run, so
  // an unplugged controller is reported once, as a gap.
  std::int64_t hands = 0;
  std::int64_t last_hand_us = trial_first_us;
  bool in_run = false;
  std::int64_t longest_no_hand_us = 0;
  for (const HandFrame* row : device.rows) {
    if (!row->hand_present) {
      in_run = true;
      continue;
    }
    ++hands;
    if (in_run) longest_no_hand_us = std::max(longest_no_hand_us, row->timestamp_us - last_hand_us);
    in_run = false;
    last_hand_us = row->timestamp_us;
  }
  if (in_run) longest_no_hand_us = std::max(longest_no_hand_us, trial_last_us - last_hand_us);
  q.hand_fraction = static_cast<double>(hands) / static_cast<double>(q.frames);
  q.longest_no_hand_s = seconds(longest_no_hand_us);
  return q;
}

}  // namespace lmc::trial_quality_detail
