#include "ui/app/workbench_shell.h"

#include <imgui.h>

#include <cstdio>
#include <utility>

#include "ui/tabs/tab_registry.h"

namespace lmc::ui {

WorkbenchShell::WorkbenchShell(ShellStartup startup) {
  context_->record_startup() = std::move(startup.record);
  for (const auto& info : tab_registry()) {
    tabs_.push_back(info.make(*this, *context_));
    ids_.push_back(info.id);
  }
  active_id_ = ids_.empty() ? std::string() : ids_.front();
  if (!startup.tab.empty()) select_tab(startup.tab);
}

WorkbenchShell::~WorkbenchShell() = default;

void WorkbenchShell::set_status(const std::string& text, bool is_error) {
  status_text_ = text;
  status_is_error_ = is_error;
}

bool WorkbenchShell::select_tab(const std::string& id) {
  for (const auto& known : ids_) {
    if (known == id) {
      pending_select_ = id;
      return true;
    }
  }
  return false;
}

bool WorkbenchShell::any_unsaved() const {
  for (const auto& t : tabs_) {
    if (t->has_unsaved_changes()) return true;
  }
  return false;
}

void WorkbenchShell::request_quit() {
  if (any_unsaved()) {
    quit_prompt_open_ = true;
  } else {
    quit_requested_ = true;
  }
}

std::string WorkbenchShell::window_title() const {
  std::string title = "LMC Workbench";
  for (size_t i = 0; i < tabs_.size(); ++i) {
    if (ids_[i] == active_id_) {
      const std::string doc = tabs_[i]->document_title();
      if (!doc.empty()) title = doc + " — " + title;
    }
  }
  return title;
}

void WorkbenchShell::frame() {
  const auto start = std::chrono::steady_clock::now();
  for (auto& t : tabs_) t->update();

  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->WorkPos);
  ImGui::SetNextWindowSize(vp->WorkSize);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_MenuBar |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6, 4));
  ImGui::Begin("##workbench", nullptr, flags);
  ImGui::PopStyleVar(2);
  draw_menu();

  const float status_height = ImGui::GetFrameHeight() + 4.0f;
  if (ImGui::BeginTabBar("##tabs")) {
    for (size_t i = 0; i < tabs_.size(); ++i) {
      const auto& info = tab_registry()[i];
      ImGuiTabItemFlags tab_flags = 0;
      if (pending_select_ == ids_[i]) tab_flags |= ImGuiTabItemFlags_SetSelected;
      if (ImGui::BeginTabItem(info.title.c_str(), nullptr, tab_flags)) {
        active_id_ = ids_[i];
        ImGui::BeginChild("##tab_content", ImVec2(0, -status_height), false);
        tabs_[i]->draw();
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
    }
    ImGui::EndTabBar();
  }
  pending_select_.clear();
  draw_status_bar(status_height);
  ImGui::End();
  draw_quit_prompt();

  if (show_about_) {
    ImGui::SetNextWindowSize(ImVec2(460, 0), ImGuiCond_Appearing);
    if (ImGui::Begin("About LMC Workbench", &show_about_, ImGuiWindowFlags_NoCollapse)) {
      ImGui::Text("LMC Workbench %s", LMC_VERSION);
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextUnformatted(
          "Design, record and analyse hand measurements with several Ultraleap Leap Motion "
          "Controllers. The same engine runs headless as the `lmc` command.");
      ImGui::PopTextWrapPos();
    }
    ImGui::End();
  }
  frame_cpu_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  last_frame_start_ = start;
}

void WorkbenchShell::draw_menu() {
  if (!ImGui::BeginMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) request_quit();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    for (size_t i = 0; i < tabs_.size(); ++i) {
      if (ImGui::MenuItem(tab_registry()[i].title.c_str(), nullptr, active_id_ == ids_[i])) select_tab(ids_[i]);
    }
    ImGui::Separator();
    ImGui::MenuItem("Frame-time readout", nullptr, &show_frame_time_);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("About")) show_about_ = true;
    ImGui::EndMenu();
  }
  ImGuiIO& io = ImGui::GetIO();
  // ImGui 1.86 has no ImGuiKey_Q; its GLFW backend indexes KeysDown by GLFW key code ('Q').
  if (io.KeyCtrl && ImGui::IsKeyPressed('Q', false)) request_quit();
  ImGui::EndMenuBar();
}

void WorkbenchShell::draw_status_bar(float height) {
  ImGui::Separator();
  ImGui::BeginChild("##status", ImVec2(0, height - 6.0f), false, ImGuiWindowFlags_NoScrollbar);
  if (status_is_error_) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", status_text_.c_str());
  } else {
    ImGui::TextUnformatted(status_text_.c_str());
  }
  if (show_frame_time_) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "frame CPU %.2f ms | %.0f fps", frame_cpu_ms_, ImGui::GetIO().Framerate);
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(buf).x - 12.0f);
    ImGui::TextUnformatted(buf);
  }
  ImGui::EndChild();
}

void WorkbenchShell::draw_quit_prompt() {
  if (quit_prompt_open_) {
    ImGui::OpenPopup("Quit with unsaved changes?");
    quit_prompt_open_ = false;
  }
  if (ImGui::BeginPopupModal("Quit with unsaved changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted("Some work has not been saved. Quit anyway and lose it?");
    if (ImGui::Button("Quit without saving")) {
      quit_requested_ = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace lmc::ui
