#include "core/visibility/visibility_kernel.h"

#include "core/visibility/visibility_tests.h"

namespace lmc {

FingerBits visible_fingers(const PreparedFrame&, const DeviceView&, const VisibilityLimits&) { return 0; }

void device_visibility(const DeviceView& device, std::span<const PreparedFrame> frames, const VisibilityLimits& limits,
                       std::span<FingerBits> out) {
  for (size_t j = 0; j < frames.size(); ++j) out[j] = visible_fingers(frames[j], device, limits);
}

VisibilityTable compute_visibility(std::span<const DeviceView> devices, std::span<const PreparedFrame> frames,
                                   const VisibilityParams& params) {
  VisibilityTable t;
  t.devices = static_cast<int>(devices.size());
  t.frames = static_cast<int>(frames.size());
  t.bits.assign(devices.size() * frames.size(), 0);
  const VisibilityLimits lim = make_limits(params);
  for (size_t d = 0; d < devices.size(); ++d) {
    device_visibility(devices[d], frames, lim, std::span<FingerBits>(t.bits).subspan(d * frames.size(), frames.size()));
  }
  return t;
}

VisibilityTable compute_visibility(const Layout& layout, std::span<const PreparedFrame> frames,
                                   double phalanx_radius_mm) {
  std::vector<DeviceView> views;
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  return compute_visibility(views, frames, VisibilityParams::from_sensor(layout.sensor, phalanx_radius_mm));
}

}  // namespace lmc
