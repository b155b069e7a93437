#include "ui/tabs/devices/live_hands_panel.h"

#include <imgui.h>

#include <string>

#include "ui/model/devices/fusion_readout.h"
#include "ui/widgets/live_hands_view.h"

namespace lmc::ui {

void LiveHandsPanel::draw() {
  const DevicesState& s = *state_;
  const DevicesViewModel& vm = s.view();
  if (vm.running()) {
    ImGui::PushTextWrapPos(0.0f);  // two lines in a narrow window rather than cut at its edge
    ImGui::TextDisabled("%s", fusion_latency_line(vm.fusion_stats()).c_str());
    ImGui::PopTextWrapPos();
  }
  const auto& ghosts = s.ghosts();
  const std::string caption =
      ghosts.empty() ? "World frame (mm), one colour per device; the fused hand thick, fingers by how many controllers "
                       "see them (red none, orange 1, yellow 2, green 3+). Drag to orbit, wheel to zoom."
                     : "Calibration result: thin outlines = where the layout puts each controller now, bold boxes = "
                       "where the calibration puts it, a line joins the two. Drag to orbit, wheel to zoom.";
  draw_live_hands_view("live_canvas", camera_, vm.layout(), vm.hands(), caption, vm.fused() ? &*vm.fused() : nullptr,
                       ghosts.empty() ? nullptr : &ghosts);
}

}  // namespace lmc::ui
