// The Devices tab's pictures: the simulated rig streaming (its controllers' rows, the live hands),
// then "devices-calibrate": a finished calibration on the simulated rig with injected errors (three
// controllers turned, every controller shifted up to 15 mm), so the corrections and the ghost
// controllers show.
#include <string>
#include <vector>

#include "ui/app/capture/capture_scratch.h"
#include "ui/app/capture/tab_capture.h"
#include "ui/tabs/devices/devices_tab.h"

namespace lmc::ui {
namespace {

class DevicesCapture final : public TabCapture {
 public:
  explicit DevicesCapture(DevicesTab& tab) : state_(tab.state()) {}

  int prepare() override {
    const DevicesViewModel& vm = state_.view();
    if (!vm.running() || vm.backend() != "sim") state_.start("sim");
    return 30;
  }

  bool busy() const override {
    const DevicesViewModel& vm = state_.view();
    return (vm.running() && !vm.all_streaming()) || state_.calibration().busy();
  }

  std::vector<std::string> extra_captures() const override { return {"devices-calibrate"}; }

  void prepare_extra(const std::string& name) override {
    if (name != "devices-calibrate") return;
    devices::SimConfig sim;
    sim.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
    sim.calibration_rotations_deg["LMC3"] = Eigen::Vector3d(4, 0, 0);
    sim.calibration_rotations_deg["LMC4"] = Eigen::Vector3d(0, 0, -3);
    sim.calibration_random_translation_mm = 15;
    if (!state_.start("sim", sim).empty()) return;
    const auto dir = scratch_.fresh("calibration");
    if (const std::string err = state_.calibration().record(dir, {}); !err.empty()) state_.report(err, true);
  }

 private:
  DevicesState& state_;
  CaptureScratch scratch_;  // removed after the shell: the rig has stopped recording into it
};

}  // namespace

std::unique_ptr<TabCapture> make_devices_capture(DevicesTab& tab) {
  return std::make_unique<DevicesCapture>(tab);
}

}  // namespace lmc::ui
