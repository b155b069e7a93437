#include "ui/tabs/record/record_setup_panel.h"

#include "ui/widgets/palette.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace lmc::ui {
namespace {

const ImVec4& kProblem = palette::kError;

// The field's problem, in red right under it (nothing when it is fine).
void problem_line(const std::string& problem) {
  if (problem.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, kProblem);
  ImGui::TextWrapped("  %s", problem.c_str());
  ImGui::PopStyleColor();
}

void hint(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("%s", text);
}

}  // namespace

SetupAction RecordSetupPanel::draw(const std::vector<SessionListing>& sessions, const std::string& error) {
  anchors_.clear();  // only what this frame drew
  SetupAction action = draw_new_session();
  if (const SetupAction resume = draw_resume(sessions); resume != SetupAction::kNone) action = resume;
  if (!error.empty()) {
    ImGui::Spacing();
    ImGui::PushStyleColor(ImGuiCol_Text, kProblem);
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
  }
  return action;
}

// The new session's fields, each with its problem under it, and Create.
SetupAction RecordSetupPanel::draw_new_session() {
  RecordSetupForm& f = form_;
  const SetupFormProblems problems = check_setup_form(f);
  WidgetAnchors* anchors = &anchors_;
  SetupAction action = SetupAction::kNone;
  ImGui::TextUnformatted("New subject session");
  ImGui::Separator();
  ImGui::PushItemWidth(260);
  ImGui::InputText("Subject id", f.subject, sizeof f.subject);
  hint("(pseudonymous: letters, digits, _ and -)");
  problem_line(problems.subject);
  ImGui::Combo("Hand", &f.handedness, "right\0left\0");
  ImGui::InputFloat("Hand length (mm)", &f.hand_length_mm, 0, 0, "%.0f");
  hint("(optional, 0 = not measured; wrist crease to middle fingertip)");
  problem_line(problems.hand_length);
  ImGui::InputFloat("Hand breadth (mm)", &f.hand_breadth_mm, 0, 0, "%.0f");
  hint("(optional; across the knuckles)");
  problem_line(problems.hand_breadth);
  ImGui::InputText("Operator", f.operator_name, sizeof f.operator_name);
  ImGui::InputText("Notes", f.notes, sizeof f.notes);
  const char* current =
      f.protocols.empty() ? "(none shipped)" : f.protocols[static_cast<size_t>(f.protocol)].label.c_str();
  if (ImGui::BeginCombo("Protocol", current)) {
    for (size_t i = 0; i < f.protocols.size(); ++i)
      if (ImGui::Selectable(f.protocols[i].label.c_str(), static_cast<int>(i) == f.protocol))
        f.protocol = static_cast<int>(i);
    ImGui::EndCombo();
  }
  if (problems.protocol.empty() && !f.protocols.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 760.0F);
    ImGui::TextDisabled("  %s", f.protocols[static_cast<size_t>(f.protocol)].description.c_str());
    ImGui::PopTextWrapPos();
  }
  problem_line(problems.protocol);
  ImGui::InputText("Vicon trigger", f.vicon, sizeof f.vicon);
  hint("(HOST[:PORT]; empty: no Vicon)");
  problem_line(problems.vicon);
  ImGui::InputText("Vicon database", f.vicon_database, sizeof f.vicon_database);
  hint("(optional: where Nexus stores the trials)");
  problem_line(problems.vicon_database);
  if (ImGui::InputText("Sessions folder", f.sessions_root, sizeof f.sessions_root))
    action = SetupAction::kRefreshSessions;  // the resume list below follows it
  if (anchors) anchors->remember("sessions_root");
  hint("(your data folder, outside the program)");
  ImGui::InputText("Folder", f.folder, sizeof f.folder);
  hint("(empty: <sessions folder>/<subject>-<date>)");
  problem_line(problems.folder);
  ImGui::Separator();
  ImGui::Combo("Controllers", &f.backend, "simulated rig\0Leap Motion controllers (LeapC)\0");
  if (f.backend == 0) ImGui::Checkbox("Simulated time (as fast as the machine can)", &f.fast);
  ImGui::PopItemWidth();
  ImGui::BeginDisabled(problems.any());
  if (ImGui::Button("Create session and go to pre-flight", ImVec2(300, 0))) action = SetupAction::kCreate;
  if (anchors) anchors->remember("create");
  ImGui::EndDisabled();
  if (problems.any()) hint("(fix the red lines first)");

  return action;
}

// A session folder to open, and the sessions folder's sessions (a click fills the folder in, a
// double click opens it).
SetupAction RecordSetupPanel::draw_resume(const std::vector<SessionListing>& sessions) {
  RecordSetupForm& f = form_;
  WidgetAnchors* anchors = &anchors_;
  SetupAction action = SetupAction::kNone;
  ImGui::Spacing();
  ImGui::Spacing();
  ImGui::TextUnformatted("Or resume a session");
  ImGui::Separator();
  ImGui::PushItemWidth(420);
  ImGui::InputText("Session folder", f.open_folder, sizeof f.open_folder);
  ImGui::PopItemWidth();
  ImGui::SameLine();
  ImGui::BeginDisabled(f.open_folder[0] == '\0');
  if (ImGui::Button("Open")) action = SetupAction::kOpen;
  if (anchors) anchors->remember("open");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::SmallButton("Refresh list")) action = SetupAction::kRefreshSessions;
  if (sessions.empty()) ImGui::TextDisabled("No sessions in %s yet.", f.sessions_folder().string().c_str());
  size_t lines = sessions.size();
  for (size_t i = 0; i < sessions.size(); ++i) {
    if (!sessions[i].group.empty() && (i == 0 || sessions[i - 1].group != sessions[i].group)) ++lines;  // its heading
  }
  const float list_h = std::min(160.0F, 2.0F * ImGui::GetStyle().WindowPadding.y +
                                            ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(lines));
  if (!sessions.empty() && ImGui::BeginChild("sessions", ImVec2(0, list_h), true)) {
    const std::string* group = nullptr;
    for (const auto& s : sessions) {
      // The list comes grouped (list_sessions): a heading where a folder's sessions begin, and its
      // sessions indented under it.
      if (group == nullptr || *group != s.group) {
        if (group != nullptr && !group->empty()) ImGui::Unindent();
        group = &s.group;
        if (!group->empty()) {
          ImGui::TextDisabled("%s/", group->c_str());
          ImGui::Indent();
        }
      }
      char label[700];
      if (!s.problem.empty())
        std::snprintf(label, sizeof label, "%s   cannot be read: %s", s.dir.filename().string().c_str(),
                      s.problem.c_str());
      else
        std::snprintf(label, sizeof label, "%s   %s, %s, %d of %d accepted%s", s.dir.filename().string().c_str(),
                      s.subject.c_str(), s.protocol.c_str(), s.accepted, s.total,
                      s.interrupted > 0 ? ", a trial was cut off" : "");
      if (ImGui::Selectable(label, s.dir.string() == f.open_folder))
        std::snprintf(f.open_folder, sizeof f.open_folder, "%s", s.dir.string().c_str());
      if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) action = SetupAction::kOpen;
    }
    if (group != nullptr && !group->empty()) ImGui::Unindent();
  }
  if (!sessions.empty()) ImGui::EndChild();
  return action;
}

}  // namespace lmc::ui
