#include "core/hand/reference_poses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <numbers>

namespace lmc {
namespace {

constexpr std::array<std::string_view, kNumHandOrientations> kOrientationNames = {"horizontal", "vertical"};
constexpr std::array<std::string_view, kNumHandMotions> kMotionNames = {"open", "index", "thumb", "wrist-flexion",
                                                                        "wrist-extension"};

}  // namespace

std::string_view orientation_name(HandOrientation o) {
  const int i = static_cast<int>(o);
  return i >= 0 && i < kNumHandOrientations ? kOrientationNames[static_cast<size_t>(i)] : std::string_view{};
}

std::string_view motion_name(HandMotion m) {
  const int i = static_cast<int>(m);
  return i >= 0 && i < kNumHandMotions ? kMotionNames[static_cast<size_t>(i)] : std::string_view{};
}

std::optional<HandOrientation> orientation_from_name(std::string_view name) {
  for (int i = 0; i < kNumHandOrientations; ++i) {
    if (kOrientationNames[static_cast<size_t>(i)] == name) return static_cast<HandOrientation>(i);
  }
  return std::nullopt;
}

std::optional<HandMotion> motion_from_name(std::string_view name) {
  for (int i = 0; i < kNumHandMotions; ++i) {
    if (kMotionNames[static_cast<size_t>(i)] == name) return static_cast<HandMotion>(i);
  }
  return std::nullopt;
}

std::string_view orientation_words(HandOrientation o) {
  return o == HandOrientation::kHorizontal ? "palm down" : "palm left";
}

std::string_view motion_words(HandMotion m) {
  switch (m) {
    case HandMotion::kOpen:
      return "open hand";
    case HandMotion::kIndexFlexion:
      return "index flexion";
    case HandMotion::kThumbFlexion:
      return "thumb flexion";
    case HandMotion::kWristFlexion:
      return "wrist flexion";
    case HandMotion::kWristExtension:
      return "wrist extension";
  }
  return "motion";
}

std::string pose_label_name(HandOrientation o, HandMotion m) {
  return std::string(orientation_name(o)) + "/" + std::string(motion_name(m));
}

// Active ranges of motion (AAOS-style norms, docs/algorithms/hand-points.md): finger MCP flexion 90°, PIP 100°,
// DIP 80°; thumb MCP 55°, IP 80° (CMC flexion ~30° across the palm, our choice); wrist flexion
// 75°, extension 70°.
const MotionRanges& motion_ranges() {
  static const MotionRanges r;
  return r;
}

HandJointAngles motion_angles(HandMotion motion, double progress) {
  const double p = std::clamp(progress, 0.0, 1.0);
  const MotionRanges& r = motion_ranges();
  HandJointAngles a;
  switch (motion) {
    case HandMotion::kOpen:
      break;
    case HandMotion::kIndexFlexion:
      a.finger(Digit::kIndex) = {p * r.index_mcp_deg, 0.0, p * r.index_pip_deg, p * r.index_dip_deg};
      break;
    case HandMotion::kThumbFlexion:
      a.thumb = {p * r.thumb_cmc_deg, 0.0, p * r.thumb_mcp_deg, p * r.thumb_ip_deg};
      break;
    case HandMotion::kWristFlexion:
      a.wrist_flexion_deg = p * r.wrist_flexion_deg;
      break;
    case HandMotion::kWristExtension:
      a.wrist_flexion_deg = -p * r.wrist_extension_deg;
      break;
  }
  return a;
}

HandPlacement reference_placement(const HandModel& model, HandOrientation orientation, const HandJointAngles& angles) {
  HandPlacement pl;
  if (orientation == HandOrientation::kVertical) {
    // Roll −90° about the forearm axis (world z): palm normal −y → −x (the subject's left, who
    // sits at +z facing −z), thumb −x → +y (up).
    pl.rotation = Eigen::AngleAxisd(-std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  const Eigen::Vector3d palm_target(0.0, kReferencePalmHeight_mm, 0.0);
  pl.wrist_mm = palm_target - pl.rotation * model.palm_position(angles);
  return pl;
}

HandFrame reference_pose(const HandModel& model, HandOrientation orientation, HandMotion motion) {
  const HandJointAngles angles = motion_angles(motion, motion == HandMotion::kOpen ? 0.0 : 1.0);
  return model.pose(angles, reference_placement(model, orientation, angles));
}

HandFrame motion_pose(const HandModel& model, HandOrientation orientation, HandMotion motion, double progress) {
  HandFrame f =
      model.pose(motion_angles(motion, std::clamp(progress, 0.0, 1.0)), reference_placement(model, orientation));
  f.hand_present = true;
  return f;
}

}  // namespace lmc
