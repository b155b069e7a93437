#include "ui/tabs/review/review_open_panel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/common/paths.h"

namespace lmc::ui {
namespace {

// The simulated subject sessions scripts/run records under sessions/demo/ (S01, S02) when missing.
std::vector<std::filesystem::path> demo_session_dirs() {
  std::vector<std::filesystem::path> dirs;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(demo_sessions_dir(), ec)) {
    if (std::filesystem::exists(e.path() / "session.json", ec)) dirs.push_back(e.path());
  }
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

}  // namespace

void ReviewOpenPanel::draw() {
  anchors_.clear();  // only what this frame drew
  ReviewState& state = *state_;
  if (ImGui::Button("Open folder...")) {
    std::error_code ec;
    const auto start =
        std::filesystem::is_directory(sessions_dir(), ec) ? sessions_dir() : std::filesystem::current_path();
    browser_.open(FileBrowser::Mode::kOpen, start);
  }
  anchors_.remember("open");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Choose any file in a subject session or a folder of trials (session.json, an LMC_*.txt); its folder opens.");
  }
  if (const auto sample = study_sample_dir(); !sample.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Study sample trial")) state.open_folder(sample);
    anchors_.remember("sample");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The study's published trial Naiv_Static101 with its Vicon file:\n%s", sample.string().c_str());
  }
  if (const auto demo = demo_session_dirs(); !demo.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Demo sessions")) {
      state.open_folders(demo);
    }
    anchors_.remember("demo");
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%zu simulated subject session(s) of the demo protocol (scripts/run recorded them) in\n%s",
                        demo.size(), demo_sessions_dir().string().c_str());
    }
  }
  if (const auto chosen = browser_.draw()) {
    std::error_code ec;
    state.open_folder(std::filesystem::is_directory(*chosen, ec) ? *chosen : chosen->parent_path());
  }
}

}  // namespace lmc::ui
