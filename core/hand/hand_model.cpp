#include "core/hand/hand_model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/angles.h"
#include "core/common/error.h"

namespace lmc {
namespace {

Eigen::Matrix3d rot_x(double deg) {
  return Eigen::AngleAxisd(deg * kRadPerDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d rot_y(double deg) {
  return Eigen::AngleAxisd(deg * kRadPerDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rot_z(double deg) {
  return Eigen::AngleAxisd(deg * kRadPerDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Rotation A with A·(0, 0, −1) = r and A's y axis as close to +y as the yaw/pitch split allows:
// A = Ry(yaw)·Rx(pitch), yaw = atan2(−r.x, −r.z), pitch = asin(r.y).
Eigen::Matrix3d aim(const Eigen::Vector3d& r) {
  const double yaw = std::atan2(-r.x(), -r.z()) / kRadPerDeg;
  const double pitch = std::asin(std::clamp(r.y(), -1.0, 1.0)) / kRadPerDeg;
  return rot_y(yaw) * rot_x(pitch);
}

// Buchholz et al. 1992, segment lengths as fractions of hand length (docs/algorithms/hand-points.md):
// rows thumb…little; columns metacarpal, proximal, middle, distal (thumb has no middle).
constexpr double kBuchholz[5][4] = {
    {0.251, 0.196, 0.0, 0.158},   {0.374, 0.265, 0.143, 0.097}, {0.373, 0.277, 0.170, 0.108},
    {0.336, 0.259, 0.165, 0.107}, {0.295, 0.206, 0.117, 0.093},
};

// Where the joints sit in the palm, as fractions of hand breadth HB (radio-ulnar, +x ulnar) and
// hand length HL (axial), and a small dorsal arch (mm). Our own approximation of the regressions
// in Buchholz et al. 1992: the metacarpal bases converge near the wrist, the MCPs spread over
// about 0.65·HB, the middle metacarpal continues the forearm axis.
constexpr double kBaseX[5] = {-0.20, -0.14, -0.03, 0.08, 0.17};    // × HB
constexpr double kBaseZ[5] = {-0.03, -0.04, -0.04, -0.04, -0.04};  // × HL (negative: distal)
constexpr double kBaseY[5] = {-9.0, 0.0, 1.0, 0.0, -2.0};          // mm
constexpr double kMcpX[5] = {0.0, -0.30, -0.05, 0.15, 0.33};       // × HB (thumb: derived)
constexpr double kMcpY[5] = {0.0, 0.0, 3.0, 1.0, -4.0};            // mm, the transverse arch
// Rest spread of the fingers (degrees about +y; positive turns towards the thumb, −x).
constexpr double kRestSpread[5] = {0.0, 4.0, 0.0, -4.0, -9.0};
// The thumb's metacarpal at rest: 40° radial of the forearm axis, 20° palmar.
constexpr double kThumbYaw = 40.0, kThumbPitch = -20.0;

}  // namespace

double joint_param(const HandJointAngles& a, int k) {
  switch (k) {
    case 0:
      return a.wrist_flexion_deg;
    case 1:
      return a.wrist_deviation_deg;
    case 2:
      return a.thumb.cmc_flexion_deg;
    case 3:
      return a.thumb.cmc_abduction_deg;
    case 4:
      return a.thumb.mcp_flexion_deg;
    case 5:
      return a.thumb.ip_flexion_deg;
    default:
      break;
  }
  if (k < 6 || k >= kNumHandJointParams) return 0.0;
  const auto& f = a.fingers[static_cast<size_t>((k - 6) / 4)];
  switch ((k - 6) % 4) {
    case 0:
      return f.mcp_flexion_deg;
    case 1:
      return f.mcp_abduction_deg;
    case 2:
      return f.pip_flexion_deg;
    default:
      return f.dip_flexion_deg;
  }
}

void set_joint_param(HandJointAngles& a, int k, double v) {
  switch (k) {
    case 0:
      a.wrist_flexion_deg = v;
      return;
    case 1:
      a.wrist_deviation_deg = v;
      return;
    case 2:
      a.thumb.cmc_flexion_deg = v;
      return;
    case 3:
      a.thumb.cmc_abduction_deg = v;
      return;
    case 4:
      a.thumb.mcp_flexion_deg = v;
      return;
    case 5:
      a.thumb.ip_flexion_deg = v;
      return;
    default:
      break;
  }
  if (k < 6 || k >= kNumHandJointParams) return;
  auto& f = a.fingers[static_cast<size_t>((k - 6) / 4)];
  switch ((k - 6) % 4) {
    case 0:
      f.mcp_flexion_deg = v;
      return;
    case 1:
      f.mcp_abduction_deg = v;
      return;
    case 2:
      f.pip_flexion_deg = v;
      return;
    default:
      f.dip_flexion_deg = v;
      return;
  }
}

const char* joint_param_name(int k) {
  static constexpr const char* kNames[kNumHandJointParams] = {
      "wrist_flexion",  "wrist_deviation",  "thumb_cmc_flexion", "thumb_cmc_abduction", "thumb_mcp",
      "thumb_ip",       "index_mcp",        "index_abduction",   "index_pip",           "index_dip",
      "middle_mcp",     "middle_abduction", "middle_pip",        "middle_dip",          "ring_mcp",
      "ring_abduction", "ring_pip",         "ring_dip",          "pinky_mcp",           "pinky_abduction",
      "pinky_pip",      "pinky_dip"};
  if (k < 0 || k >= kNumHandJointParams) return "";
  return kNames[k];
}

HandModel::HandModel(double hl, double hb) {
  if (!(hl > 50 && hl < 400) || !(hb > 20 && hb < 200)) {
    throw Error("hand length must be in (50, 400) mm and breadth in (20, 200) mm");
  }
  HandGeometry& g = geometry_;
  g.hand_length_mm = hl;
  g.hand_breadth_mm = hb;
  // Forearm ≈ 1.34 × hand length (the study's recordings: ~255 mm for a ~190 mm hand).
  g.forearm_length_mm = 1.34 * hl;
  for (int d = 0; d < kNumDigits; ++d) {
    const auto dd = static_cast<size_t>(d);
    g.base_mm[dd] = Eigen::Vector3d(kBaseX[d] * hb, kBaseY[d], kBaseZ[d] * hl);
    const double meta = kBuchholz[d][0] * hl;
    if (d == 0) {
      g.rest_direction[0] = rot_y(kThumbYaw) * rot_x(kThumbPitch) * Eigen::Vector3d(0, 0, -1);
      g.mcp_mm[0] = g.base_mm[0] + meta * g.rest_direction[0];
      g.phalanx_mm[0] = {kBuchholz[0][1] * hl, kBuchholz[0][3] * hl, 0.0};
    } else {
      const double dx = kMcpX[d] * hb - g.base_mm[dd].x();
      const double dy = kMcpY[d] - g.base_mm[dd].y();
      const double axial = std::sqrt(std::max(meta * meta - dx * dx - dy * dy, 1.0));
      g.mcp_mm[dd] = Eigen::Vector3d(kMcpX[d] * hb, kMcpY[d], g.base_mm[dd].z() - axial);
      g.phalanx_mm[dd] = {kBuchholz[d][1] * hl, kBuchholz[d][2] * hl, kBuchholz[d][3] * hl};
      g.rest_direction[dd] = rot_y(kRestSpread[d]) * Eigen::Vector3d(0, 0, -1);
    }
  }
}

HandModel::HandModel(const HandFrame& rec) {
  if (!rec.hand_present) throw Error("the recorded frame has no hand");
  for (const auto& p : rec.points) {
    if (!p.allFinite()) throw Error("the recorded frame has non-finite coordinates");
  }
  // Hand frame from the controller's palm vectors: canonical −z = palm direction, −y = normal.
  const Eigen::Vector3d dir = rec.point(kPalmDirection);
  const Eigen::Vector3d nrm = rec.point(kPalmNormal);
  Eigen::Vector3d ez = -dir;
  if (ez.norm() < 1e-6) throw Error("the recorded frame's palm direction is zero");
  ez.normalize();
  Eigen::Vector3d ey = -nrm - (-nrm).dot(ez) * ez;
  if (ey.norm() < 1e-6) throw Error("the recorded frame's palm normal is zero or parallel to its direction");
  ey.normalize();
  const Eigen::Vector3d ex = ey.cross(ez);
  Eigen::Matrix3d m;
  m.col(0) = ex;
  m.col(1) = ey;
  m.col(2) = ez;
  const Eigen::Vector3d wrist = rec.point(kWrist);
  auto local = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return m.transpose() * (p - wrist); };

  HandGeometry& g = geometry_;
  const Eigen::Vector3d elbow = local(rec.point(kElbow));
  g.forearm_length_mm = elbow.norm();
  g.elbow_direction = g.forearm_length_mm > 0 ? Eigen::Vector3d(elbow / g.forearm_length_mm) : Eigen::Vector3d(0, 0, 1);
  const Eigen::Vector3d mid_tip = local(rec.point(Digit::kMiddle, Joint::kEnd));
  g.hand_length_mm = mid_tip.norm();
  g.hand_breadth_mm =
      (local(rec.point(Digit::kIndex, Joint::kProxi)) - local(rec.point(Digit::kPinky, Joint::kProxi))).norm();
  Eigen::Vector3d mean_mcp = Eigen::Vector3d::Zero();
  for (int d = 1; d < kNumDigits; ++d) mean_mcp += local(rec.point(static_cast<Digit>(d), Joint::kProxi)) / 4.0;
  const Eigen::Vector3d palm = local(rec.point(kPalm));
  g.palm_fraction =
      mean_mcp.squaredNorm() > 0 ? std::clamp(palm.dot(mean_mcp) / mean_mcp.squaredNorm(), 0.0, 1.0) : 0.7;

  for (int d = 0; d < kNumDigits; ++d) {
    const auto dd = static_cast<size_t>(d);
    const Digit digit = static_cast<Digit>(d);
    auto pt = [&](Joint j) { return local(rec.point(digit, j)); };
    if (d == 0) {
      // Thumb: the controller's Meta == Proxi is the CMC, Inter the MCP, Dist the IP.
      g.base_mm[0] = pt(Joint::kProxi);
      g.mcp_mm[0] = pt(Joint::kInter);
      const Eigen::Vector3d meta = g.mcp_mm[0] - g.base_mm[0];
      g.rest_direction[0] = meta.norm() > 0 ? Eigen::Vector3d(meta.normalized()) : Eigen::Vector3d(0, 0, -1);
      g.phalanx_mm[0] = {(pt(Joint::kDist) - pt(Joint::kInter)).norm(), (pt(Joint::kEnd) - pt(Joint::kDist)).norm(),
                         0.0};
    } else {
      g.base_mm[dd] = pt(Joint::kMeta);
      g.mcp_mm[dd] = pt(Joint::kProxi);
      g.phalanx_mm[dd] = {(pt(Joint::kInter) - pt(Joint::kProxi)).norm(), (pt(Joint::kDist) - pt(Joint::kInter)).norm(),
                          (pt(Joint::kEnd) - pt(Joint::kDist)).norm()};
      // Keep the finger's spread (its proximal phalanx projected on the palm), not its flexion:
      // zero angles mean a straight finger.
      Eigen::Vector3d r = pt(Joint::kInter) - pt(Joint::kProxi);
      r.y() = 0.0;
      g.rest_direction[dd] = r.norm() > 0 ? Eigen::Vector3d(r.normalized()) : Eigen::Vector3d(0, 0, -1);
    }
  }
}

Eigen::Vector3d HandModel::rest_palm_position() const {
  const HandGeometry& g = geometry_;
  Eigen::Vector3d mean_mcp = Eigen::Vector3d::Zero();
  for (int d = 1; d < kNumDigits; ++d) mean_mcp += g.mcp_mm[static_cast<size_t>(d)] / 4.0;
  return g.palm_fraction * mean_mcp;
}

Eigen::Vector3d HandModel::palm_position(const HandJointAngles& a) const {
  const Eigen::Matrix3d qw = rot_y(a.wrist_deviation_deg) * rot_x(-a.wrist_flexion_deg);
  return qw * rest_palm_position();
}

HandFrame HandModel::pose(const HandJointAngles& a, const HandPlacement& placement) const {
  const HandGeometry& g = geometry_;
  HandFrame f;
  f.hand_present = true;
  const Eigen::Matrix3d& r = placement.rotation;
  const Eigen::Vector3d& t = placement.wrist_mm;
  auto world = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return r * p + t; };

  // Wrist: deviation about the dorsal axis (positive = radial, towards −x), flexion about x
  // (positive bends the hand towards the palm, −y).
  const Eigen::Matrix3d qw = rot_y(a.wrist_deviation_deg) * rot_x(-a.wrist_flexion_deg);
  const Eigen::Vector3d down(0, 0, -1);

  f.point(kElbow) = world(g.forearm_length_mm * g.elbow_direction);
  f.point(kWrist) = t;
  Eigen::Vector3d mean_mcp = Eigen::Vector3d::Zero();
  for (int d = 1; d < kNumDigits; ++d) mean_mcp += g.mcp_mm[static_cast<size_t>(d)] / 4.0;
  f.point(kPalm) = world(qw * (g.palm_fraction * mean_mcp));
  f.point(kPalmNormal) = r * (qw * Eigen::Vector3d(0, -1, 0));
  f.point(kPalmDirection) = r * (qw * down);

  // Thumb: CMC (Meta == Proxi), metacarpal to the MCP (Inter), proximal phalanx to the IP (Dist),
  // distal phalanx to the tip (End). Its flexion plane is rolled about its own axis so the thumb
  // flexes across the palm.
  {
    const ThumbAngles& th = a.thumb;
    const Eigen::Vector3d cmc = qw * g.base_mm[0];
    const double meta_len = (g.mcp_mm[0] - g.base_mm[0]).norm();
    const Eigen::Matrix3d t0 = qw * aim(g.rest_direction[0]) * rot_z(g.thumb_roll_deg);
    const Eigen::Matrix3d t1 = t0 * rot_y(th.cmc_abduction_deg) * rot_x(-th.cmc_flexion_deg);
    const Eigen::Vector3d mcp = cmc + meta_len * (t1 * down);
    const Eigen::Matrix3d t2 = t1 * rot_x(-th.mcp_flexion_deg);
    const Eigen::Vector3d ip = mcp + g.phalanx_mm[0][0] * (t2 * down);
    const Eigen::Matrix3d t3 = t2 * rot_x(-th.ip_flexion_deg);
    const Eigen::Vector3d tip = ip + g.phalanx_mm[0][1] * (t3 * down);
    f.point(digit_point(Digit::kThumb, Joint::kMeta)) = world(cmc);
    f.point(digit_point(Digit::kThumb, Joint::kProxi)) = world(cmc);
    f.point(digit_point(Digit::kThumb, Joint::kInter)) = world(mcp);
    f.point(digit_point(Digit::kThumb, Joint::kDist)) = world(ip);
    f.point(digit_point(Digit::kThumb, Joint::kEnd)) = world(tip);
  }
  // Fingers: abduction about the dorsal axis at the MCP (positive towards the thumb for index and
  // middle, towards the little finger for ring and pinky), then flexion at MCP, PIP, DIP.
  for (int d = 1; d < kNumDigits; ++d) {
    const auto dd = static_cast<size_t>(d);
    const FingerAngles& fa = a.fingers[dd - 1];
    const double abd = d <= 2 ? fa.mcp_abduction_deg : -fa.mcp_abduction_deg;
    const Eigen::Matrix3d f0 = qw * aim(g.rest_direction[dd]);
    const Eigen::Matrix3d f1 = f0 * rot_y(abd) * rot_x(-fa.mcp_flexion_deg);
    const Eigen::Vector3d mcp = qw * g.mcp_mm[dd];
    const Eigen::Vector3d pip = mcp + g.phalanx_mm[dd][0] * (f1 * down);
    const Eigen::Matrix3d f2 = f1 * rot_x(-fa.pip_flexion_deg);
    const Eigen::Vector3d dip = pip + g.phalanx_mm[dd][1] * (f2 * down);
    const Eigen::Matrix3d f3 = f2 * rot_x(-fa.dip_flexion_deg);
    const Eigen::Vector3d tip = dip + g.phalanx_mm[dd][2] * (f3 * down);
    f.point(digit_point(d, 0)) = world(qw * g.base_mm[dd]);
    f.point(digit_point(d, 1)) = world(mcp);
    f.point(digit_point(d, 2)) = world(pip);
    f.point(digit_point(d, 3)) = world(dip);
    f.point(digit_point(d, 4)) = world(tip);
  }
  return f;
}

}  // namespace lmc
