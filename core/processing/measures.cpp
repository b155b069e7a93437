#include "core/processing/measures.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lmc {
namespace {

constexpr std::array<std::array<int, 2>, kNumSegments> kSegments{{{7, 8},
                                                                  {8, 9},
                                                                  {11, 12},
                                                                  {12, 13},
                                                                  {13, 14},
                                                                  {16, 17},
                                                                  {17, 18},
                                                                  {18, 19},
                                                                  {21, 22},
                                                                  {22, 23},
                                                                  {23, 24},
                                                                  {26, 27},
                                                                  {27, 28},
                                                                  {28, 29}}};
// Joint angle = angle between (p0→p1) and (p2→p3) (docs/algorithms/processing.md, stage 5).
constexpr std::array<std::array<int, 4>, kNumAngles> kAngles{
    {{10, 11, 11, 12}, {11, 12, 12, 13}, {12, 13, 13, 14}, {6, 7, 7, 8}, {7, 8, 8, 9}, {3, 4, 4, 0}}};

}  // namespace

std::string_view segment_name(int s) {
  static constexpr std::array<std::string_view, kNumSegments> names{
      "Thumb_interm",  "Thumb_distal", "Index_proxi", "Index_interm", "Index_distal", "Middle_proxi",  "Middle_interm",
      "Middle_distal", "Ring_proxi",   "Ring_interm", "Ring_distal",  "Little_proxi", "Little_interm", "Little_distal"};
  return names[static_cast<size_t>(s)];
}

std::string_view finger_name(int f) {
  static constexpr std::array<std::string_view, kNumFingers> names{"Thumb", "Finger", "Middle", "Ring", "Little"};
  return names[static_cast<size_t>(f)];
}

std::string_view angle_name(int a) {
  static constexpr std::array<std::string_view, kNumAngles> names{"index_mcp", "index_pip", "index_dip",
                                                                  "thumb_mcp", "thumb_dip", "wrist"};
  return names[static_cast<size_t>(a)];
}

std::array<int, 2> segment_points(int s) {
  return kSegments[static_cast<size_t>(s)];
}

std::span<const int> finger_segments(int f) {
  // The thumb's two segments, then three for each finger: the segment indices in order. A view,
  // not a vector: the measures ask for it five times a frame.
  static constexpr std::array<int, kNumSegments> kInOrder = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13};
  if (f == 0) return std::span<const int>(kInOrder).first(2);
  return std::span<const int>(kInOrder).subspan(static_cast<size_t>(2 + 3 * (f - 1)), 3);
}

double joint_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = d - c;
  const double div = u.norm() * v.norm();
  if (div == 0.0) return 0.0;
  // A cosine a rounding step beyond ±1 (collinear segments) is clamped: numpy's arccos gave NaN
  // there, which dropped exactly-straight frames from the statistics.
  const double cosine = std::clamp(u.dot(v) / div, -1.0, 1.0);
  return std::acos(cosine) * 180.0 / std::numbers::pi;
}

FrameMeasures measure_frame(const HandTrack& track, int frame) {
  FrameMeasures m;
  for (int s = 0; s < kNumSegments; ++s) {
    const auto [a, b] = kSegments[static_cast<size_t>(s)];
    m.segment_mm[static_cast<size_t>(s)] = (track.at(frame, b) - track.at(frame, a)).norm();
  }
  for (int f = 0; f < kNumFingers; ++f) {
    double sum = 0.0;
    for (int s : finger_segments(f)) sum += m.segment_mm[static_cast<size_t>(s)];
    m.finger_mm[static_cast<size_t>(f)] = sum;
  }
  for (int a = 0; a < kNumAngles; ++a) {
    const auto& p = kAngles[static_cast<size_t>(a)];
    m.angle_deg[static_cast<size_t>(a)] =
        joint_angle_deg(track.at(frame, p[0]), track.at(frame, p[1]), track.at(frame, p[2]), track.at(frame, p[3]));
  }
  return m;
}

std::vector<FrameMeasures> measure_track(const HandTrack& track) {
  std::vector<FrameMeasures> out(static_cast<size_t>(track.frame_count));
  for (int f = 0; f < track.frame_count; ++f) out[static_cast<size_t>(f)] = measure_frame(track, f);
  return out;
}

namespace {

template <size_t N, typename Get>
void stats(const std::vector<FrameMeasures>& frames, Get get, std::array<double, N>& mn, std::array<double, N>& mx,
           std::array<double, N>* mean) {
  for (size_t k = 0; k < N; ++k) {
    double lo = kNaN, hi = kNaN, sum = 0.0;
    int count = 0;
    for (const auto& fm : frames) {
      const double v = get(fm)[k];
      if (!std::isfinite(v)) continue;
      lo = count == 0 ? v : std::min(lo, v);
      hi = count == 0 ? v : std::max(hi, v);
      sum += v;
      ++count;
    }
    mn[k] = lo;
    mx[k] = hi;
    if (mean != nullptr) (*mean)[k] = count > 0 ? sum / count : kNaN;
  }
}

}  // namespace

MeasureStats summarize(const std::vector<FrameMeasures>& frames) {
  MeasureStats s;
  stats<kNumSegments>(
      frames, [](const FrameMeasures& m) { return m.segment_mm; }, s.segment_min, s.segment_max, &s.segment_mean);
  stats<kNumFingers>(
      frames, [](const FrameMeasures& m) { return m.finger_mm; }, s.finger_min, s.finger_max, &s.finger_mean);
  stats<kNumAngles>(
      frames, [](const FrameMeasures& m) { return m.angle_deg; }, s.angle_min, s.angle_max, nullptr);
  for (size_t a = 0; a < kNumAngles; ++a) s.angle_rom[a] = s.angle_max[a] - s.angle_min[a];
  return s;
}

VisibilityCounts visibility_table(int device_id, const std::vector<FingerLabels>& labels) {
  VisibilityCounts t;
  t.device_id = device_id;
  for (const auto& row : labels) {
    for (size_t k = 0; k < kNumDigits; ++k) {
      if (row[k] < 0) {
        ++t.n_no_hand[k];
      } else if (row[k] == 0) {
        ++t.n_hidden[k];
      } else {
        ++t.n_visible[k];
      }
    }
  }
  for (size_t k = 0; k < kNumDigits; ++k) {
    const int seen = t.n_hidden[k] + t.n_visible[k];
    t.rate[k] = seen > 0 ? static_cast<double>(t.n_visible[k]) / seen : -1.0;
  }
  return t;
}

}  // namespace lmc
