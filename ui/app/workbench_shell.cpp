#include "ui/app/workbench_shell.h"

#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <utility>

#include "ui/tabs/tab_registry.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

WorkbenchShell::WorkbenchShell(ShellStartup startup) : recent_files_path_(std::move(startup.recent_files_path)) {
  const bool opened_on_a_task = startup.record.has_value() || !startup.review.empty();
  if (const char* trace = std::getenv("LMC_STATUS_TRACE"); trace != nullptr && *trace != '\0')
    status_trace_.open(trace, std::ios::app);
  context_->record_startup() = std::move(startup.record);
  context_->review_requests() = std::move(startup.review);
  if (startup.subject_screen) apply_subject_screen_request(context_->subject_screen(), *startup.subject_screen);
  if (!recent_files_path_.empty()) recent_ = RecentFiles::load(recent_files_path_);
  for (const auto& info : tab_registry()) {
    // Each tab reports under its own id: its messages stay with it when another tab is shown.
    sinks_.push_back(std::make_unique<TabStatusSink>(status_, info.id));
    tabs_.push_back(info.make(*sinks_.back(), *context_));
    ids_.push_back(info.id);
    last_document_paths_.push_back(tabs_.back()->document_path());
  }
  active_id_ = ids_.empty() ? std::string() : ids_.front();
  if (!startup.tab.empty()) select_tab(startup.tab);
  // Opened on a task (a session to resume, folders to review): the newcomer's first step would
  // only stand in the way of what the tab says about that task.
  if (opened_on_a_task) status_.dismiss_hint();
}

WorkbenchShell::~WorkbenchShell() = default;

int WorkbenchShell::tab_index(const std::string& id) const {
  for (size_t i = 0; i < ids_.size(); ++i) {
    if (ids_[i] == id) return static_cast<int>(i);
  }
  return -1;
}

int WorkbenchShell::document_tab() const {
  const int active = tab_index(active_id_);
  if (active >= 0 && !tabs_[static_cast<size_t>(active)]->document_kind().empty()) return active;
  for (size_t i = 0; i < tabs_.size(); ++i) {
    if (!tabs_[i]->document_kind().empty()) return static_cast<int>(i);
  }
  return -1;
}

void WorkbenchShell::track_recent_files() {
  for (size_t i = 0; i < tabs_.size(); ++i) {
    auto path = tabs_[i]->document_path();
    if (path == last_document_paths_[i]) continue;
    last_document_paths_[i] = path;
    if (!path || !recent_.add(*path, tabs_[i]->document_kind()) || recent_files_path_.empty()) continue;
    if (const std::string err = recent_.save(recent_files_path_); !err.empty()) {
      status_.post(ids_[i], "Recent files not kept: " + err, true);
    }
  }
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

std::string WorkbenchShell::recording_now() const {
  for (const auto& t : tabs_)
    if (std::string what = t->recording_now(); !what.empty()) return what;
  return {};
}

void WorkbenchShell::request_quit() {
  if (quit_after_stop_) return;  // already stopping, to quit once it has
  if (std::string what = recording_now(); !what.empty()) {
    recording_prompt_ = std::move(what);
  } else if (any_unsaved()) {
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
  for (size_t i = 0; i < tabs_.size(); ++i) tabs_[i]->update(ids_[i] == active_id_);
  // "Stop and keep, then quit": the trial ends on its worker; quitting goes on once it has (and
  // still asks about unsaved work).
  if (quit_after_stop_ && recording_now().empty()) {
    quit_after_stop_ = false;
    request_quit();
  }
  if (!context_->tab_request().empty()) {
    select_tab(context_->tab_request());
    context_->tab_request().clear();
  }
  handle_shell_keys();

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

  help_.draw();
  track_recent_files();
  frame_cpu_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  last_frame_start_ = start;
}

void WorkbenchShell::handle_shell_keys() {
  ImGuiIO& io = ImGui::GetIO();
  // The newcomer's hint stays until the first thing the user does, whatever it is.
  if (status_.hint_showing()) {
    bool acted = io.InputQueueCharacters.Size > 0;
    for (int b = 0; b < IM_ARRAYSIZE(io.MouseClicked); ++b) acted = acted || io.MouseClicked[b];
    for (int k = 0; k < IM_ARRAYSIZE(io.KeysDown); ++k) acted = acted || io.KeysDownDuration[k] == 0.0f;
    if (acted) status_.dismiss_hint();
  }
  // ImGui 1.86 has no ImGuiKey_Q; its GLFW backend indexes KeysDown by GLFW key code ('Q', F1 = 290).
  constexpr int kKeyF1 = 290;
  if (io.KeyCtrl && ImGui::IsKeyPressed('Q', false)) request_quit();
  if (ImGui::IsKeyPressed(kKeyF1, false)) open_help();
}

void WorkbenchShell::draw_file_menu() {
  const int doc = document_tab();
  Tab* target = doc >= 0 ? tabs_[static_cast<size_t>(doc)].get() : nullptr;
  const std::string kind = target ? target->document_kind() : std::string("document");
  // The tab's own shortcuts only act while it is showing, so only then are they advertised.
  const bool keys_live = doc >= 0 && ids_[static_cast<size_t>(doc)] == active_id_;
  const auto shortcut = [&](const char* keys) { return keys_live ? keys : nullptr; };
  const auto send = [&](FileCommand command) {
    select_tab(ids_[static_cast<size_t>(doc)]);
    target->handle_file_command(command);
  };
  ImGui::BeginDisabled(target == nullptr);
  if (ImGui::MenuItem(("New " + kind).c_str(), shortcut("Ctrl+N"))) send(FileCommand::kNew);
  if (ImGui::MenuItem(("Open " + kind + "...").c_str(), shortcut("Ctrl+O"))) send(FileCommand::kOpen);
  ImGui::EndDisabled();
  if (ImGui::BeginMenu("Open recent", !recent_.entries().empty())) {
    for (size_t i = 0; i < recent_.entries().size(); ++i) {
      const RecentFile& entry = recent_.entries()[i];
      const int owner = [&] {
        for (size_t t = 0; t < tabs_.size(); ++t) {
          if (tabs_[t]->document_kind() == entry.kind) return static_cast<int>(t);
        }
        return -1;
      }();
      std::error_code ec;
      const bool exists = std::filesystem::is_regular_file(entry.path, ec);
      ImGui::PushID(static_cast<int>(i));
      const std::string label = entry.path.filename().string() + (exists ? "" : "  (missing)");
      if (ImGui::MenuItem(label.c_str(), nullptr, false, exists && owner >= 0)) {
        select_tab(ids_[static_cast<size_t>(owner)]);
        tabs_[static_cast<size_t>(owner)]->open_document(entry.path);
      }
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", entry.path.string().c_str());
      ImGui::PopID();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Clear list")) {
      recent_ = RecentFiles();
      if (!recent_files_path_.empty()) (void)recent_.save(recent_files_path_);
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  ImGui::BeginDisabled(target == nullptr);
  if (ImGui::MenuItem(("Save " + kind).c_str(), shortcut("Ctrl+S"))) send(FileCommand::kSave);
  if (ImGui::MenuItem(("Save " + kind + " as...").c_str(), shortcut("Ctrl+Shift+S"))) send(FileCommand::kSaveAs);
  ImGui::EndDisabled();
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) request_quit();
}

void WorkbenchShell::draw_menu() {
  if (!ImGui::BeginMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    draw_file_menu();
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
    if (ImGui::MenuItem("Getting started", "F1")) open_help(HelpWindow::Section::kWalkthrough);
    if (ImGui::MenuItem("Keyboard shortcuts")) open_help(HelpWindow::Section::kShortcuts);
    ImGui::Separator();
    if (ImGui::MenuItem("About")) open_help(HelpWindow::Section::kAbout);
    ImGui::EndMenu();
  }
  ImGui::EndMenuBar();
}

void WorkbenchShell::draw_status_bar(float height) {
  ImGui::Separator();
  ImGui::BeginChild("##status", ImVec2(0, height - 6.0f), false, ImGuiWindowFlags_NoScrollbar);
  const StatusLine line = status_.shown(active_id_);
  if (status_trace_.is_open() && line.text != status_traced_) {
    status_traced_ = line.text;
    status_trace_ << active_id_ << '\t' << line.text << std::endl;
  }
  // A line wider than the bar (a 1024-pixel window) ends in "…" and shows whole on hover, rather
  // than running off the window's edge.
  std::string text = line.text;
  const float room = ImGui::GetContentRegionAvail().x - 4.0f;
  const bool cut = ImGui::CalcTextSize(text.c_str()).x > room;
  if (cut) {
    size_t lo = 0, hi = text.size();  // the longest prefix that fits with the ellipsis
    while (lo < hi) {
      const size_t mid = (lo + hi + 1) / 2;
      if (ImGui::CalcTextSize((text.substr(0, mid) + "…").c_str()).x <= room)
        lo = mid;
      else
        hi = mid - 1;
    }
    while (lo > 0 && (static_cast<unsigned char>(text[lo]) & 0xC0U) == 0x80U) --lo;  // whole UTF-8 characters
    text = text.substr(0, lo) + "…";
  }
  if (line.is_error) {
    ImGui::TextColored(palette::kError, "%s", text.c_str());
  } else if (line.is_hint) {
    ImGui::TextColored(palette::kInfo, "%s", text.c_str());
  } else {
    ImGui::TextUnformatted(text.c_str());
  }
  if (cut && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 60.0f);
    ImGui::TextUnformatted(line.text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
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
  constexpr const char* kRecordingTitle = "Quit while recording?";
  if (!recording_prompt_.empty() && !ImGui::IsPopupOpen(kRecordingTitle)) ImGui::OpenPopup(kRecordingTitle);
  if (ImGui::BeginPopupModal(kRecordingTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s. Quitting now cuts it off.", recording_prompt_.c_str());
    ImGui::TextUnformatted("Stop it (what is recorded is kept, the trial waits for a redo) and quit?");
    if (ImGui::Button("Stop, keep it and quit  [S]") || ImGui::IsKeyPressed('S', false)) {
      for (auto& t : tabs_)
        if (!t->recording_now().empty()) t->stop_recording();
      quit_after_stop_ = true;
      recording_prompt_.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    // The default: Esc or Enter keep the trial going.
    if (ImGui::Button("Keep recording  [Esc]") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) || recording_now().empty()) {
      recording_prompt_.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
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
