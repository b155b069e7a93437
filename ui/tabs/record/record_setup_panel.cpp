#include "ui/tabs/record/record_setup_panel.h"

#include <imgui.h>

#include <array>

#include "devices/vicon/vicon_trigger.h"

namespace lmc::ui {
namespace {

constexpr std::array<const char*, 2> kProtocols = {"study", "quick"};
constexpr std::array<const char*, 2> kBackends = {"sim", "leapc"};

}  // namespace

session::NewSessionSpec RecordSetupForm::spec() const {
  session::NewSessionSpec s;
  s.subject.subject_id = subject;
  s.subject.handedness = handedness == 0 ? "right" : "left";
  if (hand_length_mm > 0) s.subject.hand_length_mm = hand_length_mm;
  if (hand_breadth_mm > 0) s.subject.hand_breadth_mm = hand_breadth_mm;
  s.operator_name = operator_name;
  s.notes = notes;
  s.protocol = kProtocols.at(static_cast<size_t>(protocol));
  if (vicon[0] != '\0') {
    // The same parser as `lmc session new --vicon`, so both accept and refuse the same text.
    const devices::ViconTriggerConfig vc = devices::parse_vicon_target(vicon);
    s.vicon = {{"host", vc.host}, {"port", vc.port}};
  }
  return s;
}

RecordSettings RecordSetupForm::settings() const {
  RecordSettings r;
  r.backend = kBackends.at(static_cast<size_t>(backend));
  r.fast = fast && backend == 0;
  r.countdown_s = r.fast ? 0.0 : 3.0;
  return r;
}

SetupAction draw_record_setup_panel(RecordSetupForm& f, const std::string& error) {
  SetupAction action = SetupAction::kNone;
  ImGui::TextUnformatted("New subject session");
  ImGui::Separator();
  ImGui::PushItemWidth(260);
  ImGui::InputText("Subject id", f.subject, sizeof f.subject);
  ImGui::SameLine();
  ImGui::TextDisabled("(pseudonymous: letters, digits, _ and -)");
  ImGui::Combo("Hand", &f.handedness, "right\0left\0");
  ImGui::InputFloat("Hand length (mm)", &f.hand_length_mm, 0, 0, "%.0f");
  ImGui::SameLine();
  ImGui::TextDisabled("(optional; wrist crease to middle fingertip)");
  ImGui::InputFloat("Hand breadth (mm)", &f.hand_breadth_mm, 0, 0, "%.0f");
  ImGui::InputText("Operator", f.operator_name, sizeof f.operator_name);
  ImGui::InputText("Notes", f.notes, sizeof f.notes);
  ImGui::Combo("Protocol", &f.protocol, "study (80 trials, 2 layouts)\0quick (2 short trials, demo)\0");
  ImGui::InputText("Vicon trigger", f.vicon, sizeof f.vicon);
  ImGui::SameLine();
  ImGui::TextDisabled("(HOST[:PORT]; empty: no Vicon)");
  ImGui::InputText("Folder", f.folder, sizeof f.folder);
  ImGui::SameLine();
  ImGui::TextDisabled("(empty: sessions/<subject>-<date>)");
  ImGui::Separator();
  ImGui::Combo("Controllers", &f.backend, "simulated rig\0Leap Motion controllers (LeapC)\0");
  if (f.backend == 0) ImGui::Checkbox("Simulated time (as fast as the machine can)", &f.fast);
  ImGui::PopItemWidth();
  if (ImGui::Button("Create session and go to pre-flight", ImVec2(300, 0))) action = SetupAction::kCreate;

  ImGui::Spacing();
  ImGui::Spacing();
  ImGui::TextUnformatted("Or resume a session");
  ImGui::Separator();
  ImGui::PushItemWidth(420);
  ImGui::InputText("Session folder", f.open_folder, sizeof f.open_folder);
  ImGui::PopItemWidth();
  ImGui::SameLine();
  if (ImGui::Button("Open")) action = SetupAction::kOpen;
  if (!error.empty()) {
    ImGui::Spacing();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0F, 0.35F, 0.3F, 1.0F));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
  }
  return action;
}

}  // namespace lmc::ui
