#include "ui/tabs/review/review_sources_bar.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/common/paths.h"

namespace lmc::ui {
namespace {

// The simulated subject sessions scripts/run records under sessions/demo/ (S01, S02) when missing.
std::vector<std::filesystem::path> demo_session_dirs() {
  std::vector<std::filesystem::path> dirs;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(sessions_dir() / "demo", ec)) {
    if (std::filesystem::exists(e.path() / "session.json", ec)) dirs.push_back(e.path());
  }
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

void open_buttons(ReviewState& state, FileBrowser& browser) {
  if (ImGui::Button("Open folder...")) {
    std::error_code ec;
    const auto start =
        std::filesystem::is_directory(sessions_dir(), ec) ? sessions_dir() : std::filesystem::current_path();
    browser.open(FileBrowser::Mode::kOpen, start);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Choose any file in a subject session or a folder of trials (session.json, an LMC_*.txt); its folder opens.");
  }
  if (const auto sample = study_sample_dir(); !sample.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Study sample trial")) state.open_folder(sample);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The study's published trial Naiv_Static101 with its Vicon file:\n%s", sample.string().c_str());
  }
  if (const auto demo = demo_session_dirs(); !demo.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Demo sessions")) {
      state.open_folders(demo);
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%zu simulated subject session(s) of the demo protocol (scripts/run recorded them) in\n%s",
                        demo.size(), (sessions_dir() / "demo").string().c_str());
    }
  }
  if (const auto chosen = browser.draw()) {
    std::error_code ec;
    state.open_folder(std::filesystem::is_directory(*chosen, ec) ? *chosen : chosen->parent_path());
  }
}

// One opened folder as [name  lengths… x]: its finger-length correction (choose, or what is applied
// and remove) and close. Returns false when the folder was closed (the list changed).
bool folder_chip(ReviewState& state, ReviewBrowsers& browsers, const std::filesystem::path& folder) {
  ImGui::PushID(folder.string().c_str());
  const std::string name = folder.filename().empty() ? folder.string() : folder.filename().string();
  ImGui::TextDisabled("[%s", name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folder.string().c_str());
  ImGui::SameLine(0, 6);
  if (const FolderLengthCorrection* c = state.length_correction(folder)) {
    const bool applied = state.method() == FusionMethod::kDefault;
    ImGui::TextColored(applied ? ImVec4(0.45F, 0.85F, 0.95F, 1) : ImVec4(0.6F, 0.6F, 0.6F, 1),
                       applied ? "lengths corrected" : "lengths not corrected (reference fusion)");
    if (ImGui::IsItemHovered()) {
      const LengthCorrection& lc = c->correction;
      ImGui::BeginTooltip();
      ImGui::Text("Finger-length correction of subject %s, fitted on %s (%s)", lc.subject.c_str(), lc.fit_trial.c_str(),
                  length_source_name(lc.source));
      ImGui::Text("factors: thumb %.3f, index %.3f, middle %.3f, ring %.3f, pinky %.3f", lc.factor[0], lc.factor[1],
                  lc.factor[2], lc.factor[3], lc.factor[4]);
      ImGui::TextDisabled("%s", c->file.string().c_str());
      if (!applied)
        ImGui::TextDisabled("The reference fusion stays the study's algorithm: no correction is applied to it.");
      ImGui::EndTooltip();
    }
    ImGui::SameLine(0, 2);
    if (ImGui::SmallButton("-")) state.clear_length_correction(folder);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove the length correction of %s", name.c_str());
  } else {
    if (ImGui::SmallButton("lengths...")) {
      browsers.correction_for = folder;
      browsers.correction.open(FileBrowser::Mode::kOpen, folder);
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "Correct this subject's finger lengths after the default fusion with a file from\n"
          "lmc length-correction fit (one factor per finger; joint angles do not change).\n"
          "Score it on trials other than the one it was fitted on.");
    }
  }
  ImGui::SameLine(0, 4);
  bool open = true;
  if (ImGui::SmallButton("x")) {
    state.close_folder(folder);
    open = false;
  }
  if (open && ImGui::IsItemHovered()) ImGui::SetTooltip("Close %s", name.c_str());
  ImGui::SameLine(0, 0);
  ImGui::TextDisabled("]");
  ImGui::PopID();
  return open;
}

}  // namespace

void draw_review_sources_bar(ReviewState& state, ReviewBrowsers& browsers, ReviewExportPanel& export_panel) {
  open_buttons(state, browsers.folder);
  ImGui::SameLine();
  export_panel.draw_button(state);
  ImGui::SameLine(0, 20);
  ImGui::SetNextItemWidth(150);
  int method = state.method() == FusionMethod::kDefault ? 0 : 1;
  if (ImGui::Combo("fusion", &method, "default (ours)\0reference (study)\0")) {
    state.set_method(method == 0 ? FusionMethod::kDefault : FusionMethod::kReference);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "default: our smoother (labels and axis cut weigh each point)\nreference: the study's Kalman filter, exactly");
  }
  // What is open, each with its length correction and a close button.
  for (const auto& folder : state.folders()) {
    ImGui::SameLine();
    if (!folder_chip(state, browsers, folder)) break;  // the list changed under the loop
  }
  if (const auto chosen = browsers.correction.draw()) state.set_length_correction(browsers.correction_for, *chosen);
  const ReviewBatchJob& job = state.batch_job();
  if (job.running()) {
    char text[128];
    const auto eta = job.eta_seconds();
    if (eta) {
      std::snprintf(text, sizeof text, "%lld of %lld trials, about %.0f s left", job.done(), job.total(), *eta);
    } else {
      std::snprintf(text, sizeof text, "finding and processing trials...");
    }
    ImGui::ProgressBar(static_cast<float>(job.fraction()), ImVec2(360, 0), text);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) state.cancel();
  } else if (const ReviewBatch* b = state.batch()) {
    int failed = 0;
    for (const auto& t : b->trials) failed += t.row.status == TrialRowStatus::kFailed ? 1 : 0;
    ImGui::TextDisabled("%zu trial(s): %d processed now, %d from the cache%s", b->trials.size(), b->processed_now,
                        b->from_cache,
                        job.state() == JobState::kCancelled ? " (cancelled: the rest were left out)" : "");
    if (failed > 0) {
      ImGui::SameLine();
      ImGui::TextColored(ImVec4(0.95F, 0.45F, 0.35F, 1), "%d failed (status column says why)", failed);
    }
    if (!b->notes.empty() || !b->cache_warnings.empty()) {
      ImGui::SameLine();
      ImGui::TextDisabled("(%zu note(s))", b->notes.size() + b->cache_warnings.size());
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        for (const auto& n : b->notes) ImGui::TextUnformatted(n.c_str());
        for (const auto& n : b->cache_warnings) ImGui::TextUnformatted(n.c_str());
        ImGui::EndTooltip();
      }
    }
  }
  if (!state.problem().empty()) ImGui::TextColored(ImVec4(0.95F, 0.45F, 0.35F, 1), "%s", state.problem().c_str());
}

void draw_review_welcome(ReviewState& state, FileBrowser& browser) {
  ImGui::Spacing();
  ImGui::TextWrapped(
      "Review processed trials against Vicon: open a subject session (every accepted trial), a folder of trials, or "
      "the "
      "study's sample trial. Trials are resampled, realigned and fused on a worker thread and cached, so opening them "
      "again is instant. Click a trial to see its joint angles and finger lengths against Vicon on one time axis, with "
      "the label strip of every controller explaining each gap; the Agreement view gives Bland-Altman limits, RMSE, "
      "Pearson r and ICC across the trials shown.");
  ImGui::Spacing();
  open_buttons(state, browser);
}

}  // namespace lmc::ui
