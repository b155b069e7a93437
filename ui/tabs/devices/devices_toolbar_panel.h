#pragma once
// The Devices tab's top line: the backend (sim, leapc, replay of a
// recording), the layout the rig runs (the Layout tab's), Save with serials, and Start / Stop with
// how long the rig has run.
#include <memory>
#include <string>

#include "ui/model/devices/devices_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class DevicesToolbarPanel : public Panel {
 public:
  explicit DevicesToolbarPanel(std::shared_ptr<DevicesState> state)
      : Panel("##devices_toolbar"), state_(std::move(state)) {}
  void draw();
  // "start" or "stop" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::string backend_spec() const;
  // The dropdown shows what runs whenever that changes (the automatic LeapC start, its fallback to
  // the simulated rig, a start from elsewhere); the operator's own choice stands until then.
  void follow_running_backend();

  std::shared_ptr<DevicesState> state_;
  int backend_choice_ = 0;
  char replay_[512] = "";
  std::string followed_backend_;  // the running backend the dropdown last took
  FileBrowser save_browser_{"Save layout with serials", ".json"};
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
