#pragma once
// What the workbench's tabs share (issue #10), owned by the shell and handed to every tab it
// builds: the one layout (published by the Layout tab) and the one live rig (the device hub the
// Devices and Record tabs both drive). Declared before the tabs in the shell, so it outlives them.
// UI thread only.
#include "ui/model/current_layout.h"
#include "ui/model/devices/live_rig.h"

namespace lmc::ui {

class WorkbenchContext {
 public:
  WorkbenchContext() : rig_(layout_) {}
  WorkbenchContext(const WorkbenchContext&) = delete;
  WorkbenchContext& operator=(const WorkbenchContext&) = delete;

  CurrentLayout& layout() { return layout_; }
  const CurrentLayout& layout() const { return layout_; }
  LiveRig& rig() { return rig_; }

 private:
  CurrentLayout layout_;
  LiveRig rig_;  // after layout_: it reads it until destroyed
};

}  // namespace lmc::ui
