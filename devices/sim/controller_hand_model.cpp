#include "devices/sim/controller_hand_model.h"

#include <random>

namespace lmc::devices {
namespace controller_hand_model_detail {

// The direction of the bones meeting at joint j (mean of the non-zero ones), or zero.
Vec3 joint_bone_direction(const std::array<Vec3, kJointsPerDigit>& p, int j) {
  Vec3 sum = Vec3::Zero();
  if (j > 0 && (p[static_cast<size_t>(j)] - p[static_cast<size_t>(j - 1)]).norm() > 1e-9)
    sum += (p[static_cast<size_t>(j)] - p[static_cast<size_t>(j - 1)]).normalized();
  if (j + 1 < kJointsPerDigit && (p[static_cast<size_t>(j + 1)] - p[static_cast<size_t>(j)]).norm() > 1e-9)
    sum += (p[static_cast<size_t>(j + 1)] - p[static_cast<size_t>(j)]).normalized();
  return sum.norm() > 1e-9 ? Vec3(sum.normalized()) : Vec3::Zero();
}

}  // namespace controller_hand_model_detail

ControllerHandModel draw_controller_hand_model(const HandModelError& config, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0, 1);
  ControllerHandModel m;
  for (size_t dg = 0; dg < kNumDigits; ++dg) {
    const double factor = config.scale_spread > 0 ? 1.0 + config.scale_spread * gauss(rng) : 1.0;
    for (size_t b = 0; b < 4; ++b) m.scale[dg][b] = config.segment_scale[dg][b] * factor;
    for (size_t j = 0; j < kJointsPerDigit; ++j) {
      Vec3 o(0, config.joint_offset_mm[j], 0);
      if (config.joint_offset_spread_mm > 0)
        o += config.joint_offset_spread_mm * Vec3(gauss(rng), gauss(rng), gauss(rng));
      m.offset_local[dg][j] = o;
    }
  }
  return m;
}

void apply_controller_hand_model(const ControllerHandModel& model, HandFrame& hand) {
  // The palm's lateral axis is (about) every finger's flexion axis, so "palm side of a bone" is
  // lateral × bone: it turns with the bone as the finger curls, also past 90°, where the palm
  // normal made perpendicular to the bone would point to the back of the finger.
  const Vec3 normal = hand.point(kPalmNormal);
  const Vec3 lateral_axis = hand.point(kPalmDirection).cross(normal);
  for (int dg = 0; dg < kNumDigits; ++dg) {
    std::array<Vec3, kJointsPerDigit> truth{};
    for (int j = 0; j < kJointsPerDigit; ++j) truth[static_cast<size_t>(j)] = hand.point(digit_point(dg, j));
    std::array<Vec3, kJointsPerDigit> out = truth;
    for (int b = 0; b + 1 < kJointsPerDigit; ++b)
      out[static_cast<size_t>(b + 1)] =
          out[static_cast<size_t>(b)] + model.scale[static_cast<size_t>(dg)][static_cast<size_t>(b)] *
                                            (truth[static_cast<size_t>(b + 1)] - truth[static_cast<size_t>(b)]);
    for (int j = 0; j < kJointsPerDigit; ++j) {
      const Vec3 along = controller_hand_model_detail::joint_bone_direction(truth, j);
      if (along.isZero()) continue;  // no bone: leave the joint
      Vec3 palm_side = lateral_axis.cross(along);
      // A bone along the lateral axis (never a finger's; a thumb's at most partly): fall back on
      // the palm normal made perpendicular to the bone.
      if (palm_side.norm() < 0.3 * lateral_axis.norm()) palm_side = normal - normal.dot(along) * along;
      if (palm_side.norm() < 1e-9) continue;
      palm_side.normalize();
      const Vec3 lateral = along.cross(palm_side);
      const Vec3& o = model.offset_local[static_cast<size_t>(dg)][static_cast<size_t>(j)];
      out[static_cast<size_t>(j)] += o.x() * along + o.y() * palm_side + o.z() * lateral;
    }
    // A zero-length first bone (the thumb's Meta = Proxi) stays zero: the controller reports it so.
    if ((truth[1] - truth[0]).norm() < 1e-9) out[0] = out[1];
    for (int j = 0; j < kJointsPerDigit; ++j) hand.point(digit_point(dg, j)) = out[static_cast<size_t>(j)];
  }
}

}  // namespace lmc::devices
