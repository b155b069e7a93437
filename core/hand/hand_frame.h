#pragma once
// A *hand frame* is what one controller reports for one hand in one tracking event: 28 points and
// 2 unit vectors in the study's order (docs/algorithms/hand-points.md), plus the device bookkeeping
// the study's files carry. Coordinates are millimetres in whatever frame the producer says
// (device frame when it comes from a controller, world frame after realignment).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lmc {

using Vec3 = Eigen::Vector3d;

inline constexpr int kNumHandPoints = 30;  // 28 points + palm normal + palm direction
inline constexpr int kNumDigits = 5;
inline constexpr int kJointsPerDigit = 5;

// Index of each entry in HandFrame::points, in the study's column order.
enum HandPoint : int {
  kPalm = 0,
  kPalmNormal = 1,     // unit vector, not a point
  kPalmDirection = 2,  // unit vector, not a point
  kElbow = 3,          // "Arm Proximal"
  kWrist = 4,          // "Arm Distal"
  kFirstDigitPoint = 5,
};

enum class Digit : int { kThumb = 0, kIndex = 1, kMiddle = 2, kRing = 3, kPinky = 4 };

// Joints along a digit. Care: `kProxi` is the MCP joint (the authors' naming), and the thumb's
// metacarpal has zero length, so thumb Meta == Proxi.
enum class Joint : int { kMeta = 0, kProxi = 1, kInter = 2, kDist = 3, kEnd = 4 };

constexpr int digit_point(Digit d, Joint j) {
  return kFirstDigitPoint + static_cast<int>(d) * kJointsPerDigit + static_cast<int>(j);
}
constexpr int digit_point(int digit, int joint) {
  return kFirstDigitPoint + digit * kJointsPerDigit + joint;
}

// Base name of point i as in the study's headers: "Palm Position", "Arm Proximal",
// "Finger2_Inter", ... The x/y/z column names append ".x", ".y", ".z".
std::string_view hand_point_name(int i);
// Inverse of hand_point_name; nullopt for an unknown name.
std::optional<int> hand_point_from_name(std::string_view name);
// "thumb", "index", "middle", "ring", "pinky".
std::string_view digit_name(int digit);
// A hand point in words for people, with the file name after it: "ring finger tip (Finger4_End)",
// "thumb knuckle (Finger1_Proxi)", "palm position". The files' FingerN numbering starts at the
// thumb, which reads as a contradiction next to a finger's name unless both are shown together.
std::string hand_point_words(int i);

enum class HandType : int { kUnknown = -1, kLeft = 0, kRight = 1 };

struct HandFrame {
  int device_id = 0;              // 1-based device number in the recording (LMC1 = 1)
  std::int64_t frame_id = 0;      // device's own counter
  double frame_rate_hz = 0.0;     // device-reported rate (0 until the service knows it)
  std::int64_t timestamp_us = 0;  // device clock (LeapGetNow), microseconds
  bool hand_present = false;
  std::array<Vec3, kNumHandPoints> points{};  // valid only when hand_present

  const Vec3& point(int i) const { return points[static_cast<size_t>(i)]; }
  Vec3& point(int i) { return points[static_cast<size_t>(i)]; }
  const Vec3& point(Digit d, Joint j) const { return point(digit_point(d, j)); }
};

}  // namespace lmc
