#pragma once
// The tracking mode a controller should run in, from where the layout puts it. The Ultraleap
// service fits its hand model under an assumption about how the controller is mounted: desktop
// (looking up at the hand), screen-top (above the hand, looking down) or head-mounted (looking
// away from the wearer). A controller left in another mode by the control panel or another
// program tracks the study's hands under the wrong assumption, so a backend asks for the mode
// the layout implies and reports the mode the service answers with.
#include <string>

#include "core/layout/layout.h"

namespace lmc::devices {

enum class TrackingMode { kUnknown, kDesktop, kScreenTop, kHeadMounted };

// "desktop", "screen-top", "head-mounted", "unknown": the words the Devices tab, the sidecar's
// events and the messages use.
const char* tracking_mode_name(TrackingMode mode);

// Screen-top when the controller's viewing axis points down (it hangs above the hand), else
// desktop. The layout never implies head-mounted: no rig here is worn.
TrackingMode tracking_mode_for_pose(const DevicePose& pose);

// The mode for the controller with this serial: its layout slot's pose when the layout binds the
// serial, else desktop (the study's controllers all look up; a controller mounted above the hand
// gets screen-top once its serial is saved into its slot).
TrackingMode tracking_mode_for_serial(const Layout& layout, const std::string& serial);

}  // namespace lmc::devices
