#include "core/processing/fusion_lanes.h"

#include <algorithm>
#include <cmath>

namespace lmc {
namespace fusion_lanes_detail {

// Lane of the length of the bone from joint `from` to from + 1 of `digit` (from ≥ kRebuiltFromJoint).
constexpr int length_lane(int digit, int from) {
  return kFirstLengthLane + digit * kRebuiltBonesPerDigit + (from - kRebuiltFromJoint);
}

}  // namespace fusion_lanes_detail

void hand_to_lanes(std::span<const Vec3, kNumHandPoints> p, std::span<const float, kNumHandPoints> factors,
                   double base_var, std::span<double, kFusionLanes> value, std::span<double, kFusionLanes> variance) {
  using namespace fusion_lanes_detail;
  const auto factor = [&](int i) { return static_cast<double>(factors[static_cast<size_t>(i)]); };
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int c = 0; c < 3; ++c) {
      value[static_cast<size_t>(3 * i + c)] = p[static_cast<size_t>(i)][c];
      variance[static_cast<size_t>(3 * i + c)] = base_var * factor(i);
    }
  }
  for (int dg = 0; dg < kNumDigits; ++dg) {
    for (int j = kRebuiltFromJoint; j + 1 < kJointsPerDigit; ++j) {
      const int from = digit_point(dg, j), to = digit_point(dg, j + 1);
      const auto lane = static_cast<size_t>(length_lane(dg, j));
      value[lane] = (p[static_cast<size_t>(to)] - p[static_cast<size_t>(from)]).norm();
      variance[lane] = 2.0 * base_var * std::max(factor(from), factor(to));
    }
  }
}

void lanes_to_hand(std::span<const double, kFusionLanes> x, std::span<Vec3, kNumHandPoints> points) {
  using namespace fusion_lanes_detail;
  const auto fused_point = [&](int i) {
    return Vec3(x[static_cast<size_t>(3 * i)], x[static_cast<size_t>(3 * i + 1)], x[static_cast<size_t>(3 * i + 2)]);
  };
  for (int i = 0; i < kFirstDigitPoint; ++i) points[static_cast<size_t>(i)] = fused_point(i);
  for (int dg = 0; dg < kNumDigits; ++dg) {
    for (int j = 0; j <= kRebuiltFromJoint; ++j)
      points[static_cast<size_t>(digit_point(dg, j))] = fused_point(digit_point(dg, j));
    Vec3 at = fused_point(digit_point(dg, kRebuiltFromJoint));
    for (int j = kRebuiltFromJoint; j + 1 < kJointsPerDigit; ++j) {
      const Vec3 along = fused_point(digit_point(dg, j + 1)) - fused_point(digit_point(dg, j));
      const double n = along.norm();
      const double length = x[static_cast<size_t>(length_lane(dg, j))];
      if (!std::isfinite(n) || !std::isfinite(length)) {
        at = Vec3::Constant(std::nan(""));
      } else if (n > 0.0) {
        at += along * (std::max(length, 0.0) / n);
      }
      points[static_cast<size_t>(digit_point(dg, j + 1))] = at;
    }
  }
}

}  // namespace lmc
