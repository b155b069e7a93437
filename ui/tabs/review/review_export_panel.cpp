#include "ui/tabs/review/review_export_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "core/common/paths.h"
#include "ui/model/shell/file_manager.h"
#include "ui/widgets/progress_row.h"

namespace lmc::ui {
namespace {

const ImVec4 kErrorColour(0.95F, 0.45F, 0.35F, 1);

std::string trials_word(long long n) {
  return std::to_string(n) + (n == 1 ? " trial" : " trials");
}

std::string folder_name(const std::filesystem::path& folder) {
  return folder.filename().empty() ? folder.string() : folder.filename().string();
}

// "Exported 12 trials to …" and what was left out or stopped, in one line.
std::string outcome_line(const MotionExportOutcome& o) {
  std::string line = o.cancelled
                         ? "Cancelled: " + trials_word(o.trials) + " exported to " + o.folder.string() +
                               " before it stopped (each file is complete)"
                         : "Exported " + trials_word(o.trials) +
                               (o.bids ? " of " + std::to_string(o.subjects) + " subject(s) as a BIDS dataset" : "") +
                               " to " + o.folder.string();
  if (o.left_out > 0) line += "; " + std::to_string(o.left_out) + " left out (see the notes)";
  return line;
}

}  // namespace

ReviewExportPanel::ReviewExportPanel(std::shared_ptr<ReviewState> state, FolderOpener opener)
    : Panel("##export"), state_(std::move(state)), opener_(std::move(opener)) {
  if (!opener_) {
    opener_ = [](const std::filesystem::path& folder, std::string* error) {
      return open_in_file_manager(folder, error);
    };
  }
}

void ReviewExportPanel::open() {
  open_ = true;
  suggest_paths();
}

void ReviewExportPanel::choose(What what) {
  // A BIDS dataset and per-trial files each keep their own folder: switching the kind brings back
  // the folder last used (or suggested) for that kind, never the other kind's.
  if ((what == What::kBids) != (what_ == What::kBids)) {
    std::string current = folder_;
    std::snprintf(folder_, sizeof folder_, "%s", other_kind_folder_.c_str());
    other_kind_folder_ = std::move(current);
    std::swap(folder_typed_, other_kind_folder_typed_);
  }
  what_ = what;
  suggest_paths();
}

void ReviewExportPanel::set_folder(const std::filesystem::path& folder) {
  std::snprintf(folder_, sizeof folder_, "%s", folder.string().c_str());
  folder_typed_ = true;
  suggest_paths();
}

void ReviewExportPanel::suggest_paths() {
  if (!folder_typed_ || folder_[0] == '\0') {
    const char* stem = what_ == What::kBids ? "bids-dataset" : format_ == 0 ? "trials-c3d" : "trials-trc";
    std::snprintf(folder_, sizeof folder_, "%s", (sessions_dir() / "exports" / stem).string().c_str());
  }
  // The key names the subjects: it must not lie in the dataset, so beside it.
  if (!key_typed_) {
    const std::filesystem::path folder(folder_);
    std::snprintf(key_, sizeof key_, "%s",
                  (folder.parent_path() / (folder_name(folder) + "-subject-key.tsv")).string().c_str());
  }
}

void ReviewExportPanel::draw_button() {
  const ReviewState& state = *state_;
  anchors_.clear();  // a frame's anchors are what it drew: the button comes first
  const MotionExportJob& job = state.motion_export();
  char label[96];
  if (job.running()) {
    std::snprintf(label, sizeof label, "Exporting %lld/%lld...###review_export", job.done(), job.total());
  } else {
    std::snprintf(label, sizeof label, "Export...###review_export");
  }
  ImGui::BeginDisabled(state.folders().empty());
  if (ImGui::Button(label)) open();
  ImGui::EndDisabled();
  anchors_.remember("export.button");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(
        "The selected trial or the trials the table shows as C3D or TRC (OpenSim, Visual3D, Mokka),\n"
        "or the opened sessions as a BIDS-motion dataset, processed as the tab shows them");
  }
}

void ReviewExportPanel::draw_window() {
  ReviewState& state = *state_;
  if (!open_) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5F, 0.5F));
  ImGui::SetNextWindowSize(ImVec2(700, 440), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0F);  // over the plots, whose lines would show through
  if (ImGui::Begin("Export###review_export_window", &open_,
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    const bool running = state.motion_export().running();
    ImGui::BeginDisabled(running);
    draw_what(state);
    ImGui::Spacing();
    draw_options(state);
    ImGui::Spacing();
    draw_folder();
    ImGui::EndDisabled();
    ImGui::Separator();
    draw_run(state);
  }
  ImGui::End();
}

void ReviewExportPanel::draw_what(const ReviewState& state) {
  ImGui::TextDisabled("What");
  const int selected = state.selected();
  std::string selected_label = "The selected trial";
  if (selected >= 0 && selected < static_cast<int>(state.trials().size())) {
    const ReviewTrial& t = state.trials()[static_cast<size_t>(selected)];
    selected_label += ": " + t.job.trial + " (" + folder_name(t.folder) + ")";
  } else {
    selected_label += " (none is selected)";
  }
  const What before = what_;
  ImGui::BeginDisabled(selected < 0);
  if (ImGui::RadioButton(selected_label.c_str(), what_ == What::kSelected)) choose(What::kSelected);
  ImGui::EndDisabled();
  anchors_.remember("export.what.selected");
  const size_t shown = state.visible_trials().size();
  const std::string shown_label = "The " + trials_word(static_cast<long long>(shown)) + " the table shows (its filter)";
  if (ImGui::RadioButton(shown_label.c_str(), what_ == What::kShown)) choose(What::kShown);
  anchors_.remember("export.what.shown");
  const size_t folders = state.folders().size();
  const std::string bids_label = "The opened folders as a BIDS-motion dataset (" + std::to_string(folders) +
                                 (folders == 1 ? " folder" : " folders") + ", every trial)";
  if (ImGui::RadioButton(bids_label.c_str(), what_ == What::kBids)) choose(What::kBids);
  anchors_.remember("export.what.bids");
  if (what_ != before) {
    suggest_paths();
    started_ = false;  // the last outcome was of another kind of export
  }
}

void ReviewExportPanel::draw_options(const ReviewState& state) {
  if (what_ == What::kBids) {
    ImGui::Checkbox("Anonymise subjects (sub-01, sub-02, ...), key written to", &anonymise_);
    anchors_.remember("export.anonymise");
    ImGui::BeginDisabled(!anonymise_);
    ImGui::SetNextItemWidth(-90);
    if (ImGui::InputText("##key", key_, sizeof key_)) key_typed_ = true;
    ImGui::SameLine();
    if (ImGui::Button("Choose...##key")) {
      const std::filesystem::path key(key_);
      key_browser_.open(FileBrowser::Mode::kSave, key.parent_path(), key.filename().string());
    }
    ImGui::EndDisabled();
    if (const auto chosen = key_browser_.draw()) {
      std::snprintf(key_, sizeof key_, "%s", chosen->string().c_str());
      key_typed_ = true;
    }
  } else {
    const int format_before = format_;
    ImGui::TextUnformatted("Format");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::Combo("##format", &format_, "C3D\0TRC\0");
    anchors_.remember("export.format");
    if (format_ != format_before) suggest_paths();
    ImGui::SameLine(0, 20);
    ImGui::TextUnformatted("Axes");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    ImGui::Combo("##axes", &axes_,
                 "world (x along the table, y up, z towards the subject)\0"
                 "OpenSim (X forward, Y up, Z to the subject's right)\0");
    anchors_.remember("export.axes");
  }
  // What the points are: the fusion the table shows and each folder's length correction.
  std::string how = std::string("Processed as the tab shows them: ") +
                    (state.method() == FusionMethod::kDefault ? "default fusion" : "reference fusion (the study's)");
  std::string corrected;
  for (const auto& folder : state.folders()) {
    if (state.length_correction(folder) != nullptr && state.method() == FusionMethod::kDefault) {
      corrected += (corrected.empty() ? "" : ", ") + folder_name(folder);
    }
  }
  if (!corrected.empty()) {
    how += what_ == What::kBids
               ? "; the length corrections of " + corrected + " are not applied (one set of options per dataset)"
               : "; lengths corrected for " + corrected;
  }
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("%s", how.c_str());
  if (what_ == What::kShown) {
    std::vector<std::filesystem::path> folders;
    for (const int k : state.visible_trials()) {
      const auto& f = state.trials()[static_cast<size_t>(k)].folder;
      if (std::find(folders.begin(), folders.end(), f) == folders.end()) folders.push_back(f);
    }
    if (folders.size() > 1)
      ImGui::TextDisabled("Trials of several folders go into one subfolder per folder (subjects share trial names).");
  }
  ImGui::PopTextWrapPos();
}

void ReviewExportPanel::draw_folder() {
  ImGui::TextUnformatted("Folder");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-90);
  if (ImGui::InputText("##folder", folder_, sizeof folder_)) {
    folder_typed_ = true;
    suggest_paths();
  }
  anchors_.remember("export.folder");
  ImGui::SameLine();
  if (ImGui::Button("Choose...##folder")) {
    const std::filesystem::path folder(folder_);
    std::error_code ec;
    const auto parent = std::filesystem::is_directory(folder.parent_path(), ec) ? folder.parent_path() : sessions_dir();
    folder_browser_.open(FileBrowser::Mode::kSave, parent, folder_name(folder));
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Go to where the folder should be and type its name (it is created when missing)");
  if (const auto chosen = folder_browser_.draw()) set_folder(*chosen);
  ImGui::Checkbox("Replace files that exist", &replace_);
  anchors_.remember("export.replace");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Unticked, an export that would replace a file writes nothing and lists the files");
}

void ReviewExportPanel::start() {
  ReviewState& state = *state_;
  started_ = true;
  open_error_.clear();
  const std::filesystem::path folder(folder_);
  if (what_ == What::kBids) {
    std::optional<std::filesystem::path> key;
    if (anonymise_) key = std::filesystem::path(key_);
    state.export_bids_dataset(folder, key, replace_);
  } else {
    state.export_trial_points(what_ == What::kSelected ? TrialsToExport::kSelected : TrialsToExport::kShown, folder,
                              format_ == 0 ? ExportFormat::kC3d : ExportFormat::kTrc,
                              axes_ == 0 ? ExportAxes::kWorld : ExportAxes::kOpenSim, replace_);
  }
}

void ReviewExportPanel::draw_run(ReviewState& state) {
  const MotionExportJob& job = state.motion_export();
  if (job.running()) {
    const std::string stage =
        job.total() > 0 ? std::to_string(job.done()) + " of " + trials_word(job.total()) : "finding trials...";
    if (draw_progress_row("export.progress", job.fraction(), stage, job.elapsed_seconds(), job.eta_seconds(), true,
                          &anchors_)) {
      state.cancel_motion_export();
    }
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("%s", job.current_line().c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  const bool nothing = folder_[0] == '\0' || (what_ == What::kSelected && state.selected() < 0) ||
                       (what_ == What::kShown && state.visible_trials().empty()) ||
                       (what_ == What::kBids && state.folders().empty());
  ImGui::BeginDisabled(nothing);
  if (ImGui::Button("Export", ImVec2(120, 0))) start();
  ImGui::EndDisabled();
  anchors_.remember("export.start");
  if (started_) draw_outcome(state);
}

void ReviewExportPanel::draw_outcome(const ReviewState& state) {
  const MotionExportJob& job = state.motion_export();
  const auto outcome = job.outcome();
  ImGui::PushTextWrapPos(0);
  if (job.state() == JobState::kFailed || !outcome) {
    if (job.state() == JobState::kFailed) {
      // The first line says why; what follows (the files that exist, every trial left out) scrolls.
      const std::string error = job.error();
      const size_t cut = error.find('\n');
      ImGui::TextColored(kErrorColour, "Export failed: %s", error.substr(0, cut).c_str());
      anchors_.remember("export.error");
      if (cut != std::string::npos) {
        ImGui::BeginChild("##export_error_lines", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
        ImGui::TextUnformatted(error.c_str() + cut + 1);
        ImGui::EndChild();
      }
    }
    ImGui::PopTextWrapPos();
    return;
  }
  ImGui::SameLine();
  if (ImGui::Button("Open folder")) {
    open_error_.clear();
    if (!opener_(outcome->folder, &open_error_) && open_error_.empty()) open_error_ = "could not open the folder";
  }
  anchors_.remember("export.open_folder");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", outcome->folder.string().c_str());
  ImGui::TextUnformatted(outcome_line(*outcome).c_str());
  anchors_.remember("export.result");
  if (!open_error_.empty()) ImGui::TextColored(kErrorColour, "%s", open_error_.c_str());
  ImGui::PopTextWrapPos();
  if (!outcome->notes.empty()) {
    ImGui::TextDisabled("Notes");
    ImGui::BeginChild("##export_notes", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
    for (const auto& n : outcome->notes) ImGui::TextUnformatted(n.c_str());
    ImGui::EndChild();
  }
}

}  // namespace lmc::ui
