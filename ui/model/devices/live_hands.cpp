#include "ui/model/devices/live_hands.h"

namespace lmc::ui {

std::optional<LiveHand> live_hand(const devices::DeviceStatus& s, const Layout& layout) {
  if (s.slot_index < 0 || !s.hand_present || !s.latest || !s.connected || s.slot_index >= layout.device_count())
    return std::nullopt;
  LiveHand h;
  h.colour = s.slot_index;
  h.slot = s.slot;
  const LayoutDevice& ld = layout.devices[static_cast<size_t>(s.slot_index)];
  for (int p = 0; p < kNumHandPoints; ++p) {
    const Vec3& q = s.latest->point(p);
    // Directions turn with the controller; points also move with it.
    h.world[static_cast<size_t>(p)] =
        (p == kPalmNormal || p == kPalmDirection) ? Vec3(ld.pose.rotation() * q) : ld.to_world(q);
  }
  return h;
}

std::vector<LiveHand> live_hands(const devices::HubSnapshot& snapshot, const Layout& layout) {
  std::vector<LiveHand> out;
  for (const auto& d : snapshot.devices)
    if (auto h = live_hand(d, layout)) out.push_back(std::move(*h));
  return out;
}

}  // namespace lmc::ui
