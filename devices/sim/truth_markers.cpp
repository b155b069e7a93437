#include "devices/sim/truth_markers.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/common/error.h"

namespace lmc::devices {

TruthMarkerMap::TruthMarkerMap(ViconMapping mapping) : mapping_(std::move(mapping)) {
  const size_t n = mapping_.markers.size();
  sources_.assign(n, MarkerSource{});
  std::vector<bool> assigned(n, false);
  for (int p = 0; p < kNumHandPoints; ++p) {
    const auto& terms = mapping_.terms[static_cast<size_t>(p)];
    if (terms.size() == 1 && std::abs(terms[0].second - 1.0) < 1e-9 && !assigned[static_cast<size_t>(terms[0].first)]) {
      sources_[static_cast<size_t>(terms[0].first)] = {Source::kPoint, p};
      assigned[static_cast<size_t>(terms[0].first)] = true;
    }
  }
  for (int p = 0; p < kNumHandPoints; ++p) {
    const auto& terms = mapping_.terms[static_cast<size_t>(p)];
    if (terms.size() != 2) continue;
    const auto a = static_cast<size_t>(terms[0].first);
    const auto b = static_cast<size_t>(terms[1].first);
    if (assigned[a] || assigned[b]) continue;
    if (std::abs(terms[0].second - 0.5) > 1e-9 || std::abs(terms[1].second - 0.5) > 1e-9) continue;
    sources_[a] = {Source::kPairPlus, p};
    sources_[b] = {Source::kPairMinus, p};
    assigned[a] = assigned[b] = true;
  }
  for (size_t m = 0; m < n; ++m)
    if (!assigned[m])
      throw Error("mapping '" + mapping_.name + "': marker " + mapping_.markers[m] +
                  " is not a copy of one point or half of an averaged pair; the simulator cannot invert it");
}

std::vector<Vec3> TruthMarkerMap::markers(const HandFrame& f) const {
  Vec3 lateral = f.point(kPalmNormal).cross(f.point(kPalmDirection));
  lateral = lateral.norm() > 1e-9 ? lateral.normalized() : Vec3::UnitX();
  std::vector<Vec3> out(sources_.size());
  for (size_t m = 0; m < sources_.size(); ++m) {
    const Vec3& p = f.point(sources_[m].point);
    switch (sources_[m].source) {
      case Source::kPoint:
        out[m] = p;
        break;
      case Source::kPairPlus:
        out[m] = p + kStyloidHalfWidthMm * lateral;
        break;
      case Source::kPairMinus:
        out[m] = p - kStyloidHalfWidthMm * lateral;
        break;
    }
  }
  return out;
}

void TruthMarkerMap::make_consistent(HandFrame& f) const {
  const std::vector<Vec3> m = markers(f);
  for (int p = 0; p < kNumHandPoints; ++p) {
    const auto& terms = mapping_.terms[static_cast<size_t>(p)];
    if (terms.empty()) continue;
    Vec3 sum = Vec3::Zero();
    for (const auto& [marker, weight] : terms) sum += weight * m[static_cast<size_t>(marker)];
    f.point(p) = sum;
  }
}

TrcData truth_trc(const std::vector<HandFrame>& frames, double rate_hz, const TruthMarkerMap& map) {
  TrcData trc;
  trc.data_rate_hz = rate_hz;
  trc.camera_rate_hz = rate_hz;
  trc.units = "mm";
  trc.marker_names = map.marker_names();
  for (size_t i = 0; i < frames.size(); ++i) {
    trc.frame_numbers.push_back(static_cast<int>(i) + 1);
    trc.times_s.push_back(static_cast<double>(i) / rate_hz);
    if (frames[i].hand_present) {
      trc.positions.push_back(map.markers(frames[i]));
    } else {
      const double nan = std::nan("");
      trc.positions.emplace_back(map.marker_names().size(), Vec3(nan, nan, nan));
    }
  }
  return trc;
}

}  // namespace lmc::devices
