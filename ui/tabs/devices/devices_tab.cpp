#include "ui/tabs/devices/devices_tab.h"

#include "ui/widgets/placeholder_panel.h"

namespace lmc::ui {
namespace {

class DevicesTab final : public Tab {
 public:
  void draw() override {
    draw_placeholder_panel("Devices", "See every connected controller (or the simulated rig), which layout slot it fills and whether it is streaming.", {"Device list: serial, slot, backend, status, rate, hand present, frame age", "Live 3D view of every device's hand in the world frame", "Start and stop a test recording"});
  }
};

}  // namespace

std::unique_ptr<Tab> make_devices_tab(StatusSink&) { return std::make_unique<DevicesTab>(); }

}  // namespace lmc::ui
