#include "core/hand/palm_axes.h"

#include "core/common/nan.h"
#include "core/hand/hand_track.h"

namespace lmc {

PalmAxes estimate_palm_axes(const HandFrame& frame) {
  const Vec3 nan = Vec3::Constant(kNaN);
  const Vec3& wrist = frame.point(kWrist);
  const Vec3& middle = frame.point(Digit::kMiddle, Joint::kMeta);
  const Vec3& index = frame.point(Digit::kIndex, Joint::kMeta);
  const Vec3& pinky = frame.point(Digit::kPinky, Joint::kMeta);
  if (!is_finite(wrist) || !is_finite(middle) || !is_finite(index) || !is_finite(pinky)) return {nan, nan};
  const Vec3 along = middle - wrist;
  const Vec3 across = index - pinky;
  if (along.norm() < 1e-9 || across.norm() < 1e-9) return {nan, nan};
  const Vec3 direction = along.normalized();
  Vec3 normal = across.cross(direction);
  normal -= normal.dot(direction) * direction;
  if (normal.norm() < 1e-9) return {nan, nan};
  return {normal.normalized(), direction};
}

}  // namespace lmc
