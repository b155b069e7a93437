#include "ui/tabs/review/review_sources_panel.h"

#include <imgui.h>

#include <cstdio>
#include <string>

#include "ui/widgets/flow_row.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

bool ReviewSourcesPanel::folder_chip(const std::filesystem::path& folder) {
  ReviewState& state = *state_;
  ImGui::PushID(folder.string().c_str());
  const std::string name = folder.filename().empty() ? folder.string() : folder.filename().string();
  ImGui::TextDisabled("[%s", name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folder.string().c_str());
  ImGui::SameLine(0, 6);
  if (const FolderLengthCorrection* c = state.length_correction(folder)) {
    const bool applied = state.method() == FusionMethod::kDefault;
    ImGui::TextColored(applied ? palette::kInfo : palette::kMuted,
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
    anchors_.remember("unlength." + name);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove the length correction of %s", name.c_str());
  } else {
    if (ImGui::SmallButton("lengths...")) {
      correction_for_ = folder;
      correction_browser_.open(FileBrowser::Mode::kOpen, folder);
    }
    anchors_.remember("lengths." + name);
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
  anchors_.remember("close." + name);
  if (open && ImGui::IsItemHovered()) ImGui::SetTooltip("Close %s", name.c_str());
  ImGui::SameLine(0, 0);
  ImGui::TextDisabled("]");
  ImGui::PopID();
  return open;
}

float ReviewSourcesPanel::fusion_width() {
  return 150 + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("fusion").x;
}

namespace {

// About the width of a folder's chip: "[name", its length-correction control, "x" and "]".
float chip_width(const std::filesystem::path& folder) {
  const std::string name = folder.filename().empty() ? folder.string() : folder.filename().string();
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize(("[" + name + "]").c_str()).x + ImGui::CalcTextSize("lengths corrected").x +
         ImGui::CalcTextSize("x").x + 4 * style.FramePadding.x + 12;
}

}  // namespace

void ReviewSourcesPanel::draw() {
  anchors_.clear();  // only what this frame drew
  ReviewState& state = *state_;
  ImGui::SetNextItemWidth(150);
  int method = state.method() == FusionMethod::kDefault ? 0 : 1;
  if (ImGui::Combo("fusion", &method, "default (ours)\0reference (study)\0")) {
    state.set_method(method == 0 ? FusionMethod::kDefault : FusionMethod::kReference);
  }
  anchors_.remember("fusion");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "default: our smoother (labels and axis cut weigh each point)\nreference: the study's Kalman filter, exactly");
  }
  // What is open, each with its length correction and a close button.
  for (const auto& folder : state.folders()) {
    same_line_or_wrap(chip_width(folder));
    if (!folder_chip(folder)) break;  // the list changed under the loop
  }
  if (const auto chosen = correction_browser_.draw()) state.set_length_correction(correction_for_, *chosen);
  draw_progress();
  if (!state.problem().empty()) ImGui::TextColored(palette::kError, "%s", state.problem().c_str());
}

void ReviewSourcesPanel::draw_progress() {
  ReviewState& state = *state_;
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
    anchors_.remember("cancel");
  } else if (const ReviewBatch* b = state.batch()) {
    int failed = 0;
    for (const auto& t : b->trials) failed += t.row.status == TrialRowStatus::kFailed ? 1 : 0;
    ImGui::TextDisabled("%zu trial(s): %d processed now, %d from the cache%s", b->trials.size(), b->processed_now,
                        b->from_cache,
                        job.state() == JobState::kCancelled ? " (cancelled: the rest were left out)" : "");
    if (failed > 0) {
      ImGui::SameLine();
      ImGui::TextColored(palette::kError, "%d failed (status column says why)", failed);
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
}

}  // namespace lmc::ui
