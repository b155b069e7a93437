#pragma once
// One line for a test recording through the rig's trial engine: trial name, folder and length,
// Record / Stop recording, and where the recording is (or how the last one ended).
#include <filesystem>
#include <memory>

#include "ui/model/devices/devices_state.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class TestRecordingPanel : public Panel {
 public:
  // `folder`: where a recording goes unless the operator types another.
  TestRecordingPanel(std::shared_ptr<DevicesState> state, const std::filesystem::path& folder);
  void draw();
  // "record" or "stop_recording" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::shared_ptr<DevicesState> state_;
  char trial_[80] = "";
  char folder_[512] = "";
  double seconds_ = DevicesViewModel::kDefaultTrialSeconds;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
