#pragma once
// A parametric right hand that produces the controller's 30-point layout (hand_frame.h) from
// joint angles: forearm (elbow, wrist), palm, and for each digit the metacarpal base and the
// MCP / PIP / DIP / tip joints (thumb: CMC, MCP, IP, tip; its controller metacarpal has zero
// length so Meta == Proxi, docs/algorithms/hand-points.md).
//
// Canonical hand frame (the "horizontal" reference pose before placement): wrist joint centre at
// the origin, fingers pointing along −z (away from the subject), back of the hand up (+y), palm
// normal −y, thumb on the −x side (right hand, palm down). The forearm runs from the wrist back
// towards +z, so the elbow is at +z. Placement (HandPlacement) rotates and translates this frame
// into the world.
//
// Default segment lengths: Buchholz, Armstrong & Goldstein 1992, "Anthropometric data for
// describing the kinematics of the human hand", Ergonomics 35(3):261–273 (fractions of hand
// length HL, wrist crease to middle fingertip), default HL = 190 mm (adult male, Ibeachu et al.
// 2011) and hand breadth 85 mm (Pheasant, British adult 50th percentile). See docs/algorithms/hand-points.md.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

#include "core/hand/hand_frame.h"

namespace lmc {

// Joint angles in degrees. Positive flexion bends towards the palm; positive abduction spreads a
// finger away from the middle finger's axis (towards the thumb for the index, towards the little
// finger for ring and pinky; for the middle finger, towards the thumb); positive wrist deviation is
// radial (towards the thumb).
struct FingerAngles {
  double mcp_flexion_deg = 0;
  double mcp_abduction_deg = 0;
  double pip_flexion_deg = 0;
  double dip_flexion_deg = 0;

  bool operator==(const FingerAngles&) const = default;
};

struct ThumbAngles {
  double cmc_flexion_deg = 0;    // moves the thumb across the palm (towards the little finger)
  double cmc_abduction_deg = 0;  // moves the thumb away from the palm (palmar abduction)
  double mcp_flexion_deg = 0;
  double ip_flexion_deg = 0;

  bool operator==(const ThumbAngles&) const = default;
};

struct HandJointAngles {
  double wrist_flexion_deg = 0;    // negative = extension
  double wrist_deviation_deg = 0;  // positive = radial, negative = ulnar
  ThumbAngles thumb;
  std::array<FingerAngles, 4> fingers{};  // index, middle, ring, pinky

  FingerAngles& finger(Digit d) { return fingers[static_cast<size_t>(static_cast<int>(d) - 1)]; }
  const FingerAngles& finger(Digit d) const { return fingers[static_cast<size_t>(static_cast<int>(d) - 1)]; }

  bool operator==(const HandJointAngles&) const = default;
};

// Number of scalar joint parameters in HandJointAngles and their order for noise / generic access:
// wrist flexion, wrist deviation, thumb CMC flexion, CMC abduction, MCP, IP, then for index, middle,
// ring, pinky: MCP flexion, MCP abduction, PIP, DIP.
inline constexpr int kNumHandJointParams = 2 + 4 + 4 * 4;
double joint_param(const HandJointAngles& a, int k);
void set_joint_param(HandJointAngles& a, int k, double value_deg);
const char* joint_param_name(int k);  // "wrist_flexion", "thumb_cmc_flexion", "index_pip", ...

// Where the hand is: the canonical hand frame's rotation and the world position of the wrist.
struct HandPlacement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d wrist_mm = Eigen::Vector3d::Zero();
};

// Fixed geometry of one hand in the canonical frame (wrist at the origin, straight wrist).
struct HandGeometry {
  double hand_length_mm = 190.0;
  double hand_breadth_mm = 85.0;
  double forearm_length_mm = 255.0;  // wrist to elbow joint centre
  // Unit direction from the wrist to the elbow in the canonical frame (straight forearm: +z).
  Eigen::Vector3d elbow_direction = Eigen::Vector3d(0, 0, 1);
  // The controller's palm position lies on the line wrist → mean of the four finger MCPs, this
  // fraction of the way (measured on the study's recordings: about 0.7).
  double palm_fraction = 0.7;
  // Metacarpal base (Meta) and MCP position of each digit in the palm frame (thumb: CMC; its MCP
  // position is derived from the metacarpal direction and length at zero angles).
  std::array<Eigen::Vector3d, kNumDigits> base_mm{};
  std::array<Eigen::Vector3d, kNumDigits> mcp_mm{};
  // Phalanx lengths: proximal, middle, distal (thumb: proximal, distal, unused 0). The thumb's
  // metacarpal length is |mcp − base|.
  std::array<std::array<double, 3>, kNumDigits> phalanx_mm{};
  // Direction of each digit's proximal phalanx at zero angles (unit, canonical frame); encodes the
  // rest spread of the fingers and the thumb's rest orientation.
  std::array<Eigen::Vector3d, kNumDigits> rest_direction{};
  // Thumb: roll of the thumb's flexion plane about its own axis (degrees): 0 would flex the thumb
  // straight down like a finger; the default turns its pulp towards the fingers.
  double thumb_roll_deg = 60.0;
};

class HandModel {
 public:
  // An average adult right hand from published anthropometry (see the file comment).
  explicit HandModel(double hand_length_mm = 190.0, double hand_breadth_mm = 85.0);
  // A subject's own hand: segment lengths, metacarpal bases, MCP positions and rest directions
  // taken from one recorded frame (e.g. the first row of reference-data/optimization/Static.txt).
  // The frame's palm normal/direction define the hand frame. Throws lmc::Error when the frame has
  // no hand or its vectors are degenerate.
  explicit HandModel(const HandFrame& recorded);
  explicit HandModel(HandGeometry geometry) : geometry_(std::move(geometry)) {}

  const HandGeometry& geometry() const { return geometry_; }

  // The 30-point frame (world coordinates) for these angles at this placement. hand_present is
  // true; device bookkeeping fields are zero.
  HandFrame pose(const HandJointAngles& angles, const HandPlacement& placement = {}) const;
  // The palm position (point 0) for straight joints in the canonical frame: where reference
  // placements put the palm centre.
  Eigen::Vector3d rest_palm_position() const;
  // The palm position for these angles in the canonical frame (wrist at the origin): where a
  // placement must put it so the palm centre lands on a target while the wrist bends.
  Eigen::Vector3d palm_position(const HandJointAngles& angles) const;

 private:
  HandGeometry geometry_;
};

}  // namespace lmc
