#include "ui/tabs/devices/test_recording_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/widgets/flow_row.h"

namespace lmc::ui {

TestRecordingPanel::TestRecordingPanel(std::shared_ptr<DevicesState> state, const std::filesystem::path& folder)
    : Panel("##test_recording"), state_(std::move(state)) {
  std::snprintf(folder_, sizeof folder_, "%s", folder.string().c_str());
  std::snprintf(trial_, sizeof trial_, "%s", "test_trial_1");
}

void TestRecordingPanel::draw() {
  anchors_.clear();  // only what this frame drew
  DevicesState& s = *state_;
  const DevicesViewModel& vm = s.view();
  ImGui::TextUnformatted("Test recording");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(160);
  ImGui::InputText("##trial", trial_, sizeof trial_);
  ImGui::SameLine();
  // The folder takes what the seconds and the button leave (at least 260 px), so a path in the
  // user's data folder shows whole; the whole path is on hover either way.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float after = style.ItemSpacing.x + 90 + style.ItemInnerSpacing.x + ImGui::CalcTextSize("s").x +
                      style.ItemSpacing.x + ImGui::CalcTextSize("Stop recording").x + 2 * style.FramePadding.x;
  ImGui::SetNextItemWidth(std::max(260.0f, ImGui::GetContentRegionAvail().x - after));
  ImGui::InputText("##folder", folder_, sizeof folder_);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folder_);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::InputDouble("s##seconds", &seconds_, 0, 0, "%.0f");
  seconds_ = std::clamp(seconds_, 1.0, 3600.0);
  ImGui::SameLine();
  if (!vm.recording()) {
    if (ImGui::Button("Record")) s.start_recording(folder_, trial_, seconds_);
    anchors_.remember("record");
  } else {
    if (ImGui::Button("Stop recording")) s.stop_recording();
    anchors_.remember("stop_recording");
  }
  if (auto p = vm.recording_progress()) {
    char line[256];
    if (vm.recording()) {
      std::snprintf(line, sizeof line, "%s: %s, %.1f s recorded, %lld frames written, %lld dropped", p->trial.c_str(),
                    p->phase.c_str(), p->recording_s, static_cast<long long>(p->frames_written),
                    static_cast<long long>(p->frames_dropped));
    } else {
      std::snprintf(line, sizeof line, "last: %s, %.1f s, %lld frames", p->trial.c_str(), p->recording_s,
                    static_cast<long long>(p->frames_written));
    }
    same_line_or_wrap(ImGui::CalcTextSize(line).x);
    if (vm.recording()) {
      ImGui::TextUnformatted(line);
    } else {
      ImGui::TextDisabled("%s", line);
    }
  }
}

}  // namespace lmc::ui
