#pragma once
// Each controller's latest hand, realigned into the world frame with its layout slot's pose, for
// the live views of the Devices and Record tabs: where the hands disagree, a controller is
// misplaced (or its slot is wrong). One rule, used by both tabs.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "devices/device_hub.h"
#include "ui/scene/colour_maps.h"

namespace lmc::ui {

struct LiveHand {
  int colour = 0;  // index into device_colour(): the slot's index
  std::string slot;
  std::array<Vec3, kNumHandPoints> world{};
};

// The device's hand in the world frame, or nothing when it has no slot, no hand or no frame.
std::optional<LiveHand> live_hand(const devices::DeviceStatus& device, const Layout& layout);
// Every assigned, connected device's hand, in snapshot order.
std::vector<LiveHand> live_hands(const devices::HubSnapshot& snapshot, const Layout& layout);

}  // namespace lmc::ui
