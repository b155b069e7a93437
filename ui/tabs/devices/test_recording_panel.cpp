#include "ui/tabs/devices/test_recording_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace lmc::ui {

TestRecordingPanel::TestRecordingPanel(std::shared_ptr<DevicesState> state, const std::filesystem::path& folder)
    : state_(std::move(state)) {
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
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("##folder", folder_, sizeof folder_);
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
    ImGui::SameLine();
    if (vm.recording()) {
      ImGui::Text("%s: %s, %.1f s recorded, %lld frames written, %lld dropped", p->trial.c_str(), p->phase.c_str(),
                  p->recording_s, static_cast<long long>(p->frames_written), static_cast<long long>(p->frames_dropped));
    } else {
      ImGui::TextDisabled("last: %s, %.1f s, %lld frames", p->trial.c_str(), p->recording_s,
                          static_cast<long long>(p->frames_written));
    }
  }
}

}  // namespace lmc::ui
