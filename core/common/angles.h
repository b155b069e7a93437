#pragma once
// Degrees ↔ radians: layouts, poses and the UI speak degrees, Eigen and <cmath> radians.
#include <numbers>

namespace lmc {

inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

}  // namespace lmc
