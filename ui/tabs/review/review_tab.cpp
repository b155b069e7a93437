// The Review tab: the folders a researcher opened, processed in the background into one table
// of trials, the selected trial against Vicon with its 3D replay, agreement across the trials shown
// and the study's tables, and exports. Its state is ui/model/review/review_state.h; the panels
// beside this file draw it (open buttons, Export..., sources bar, trial table, trial view with the
// replay, agreement, study tables, the welcome shown while nothing is open) and this file lays them
// out and reports finished work on the status bar.
#include "ui/tabs/review/review_tab.h"

#include <imgui.h>

#include <memory>

#include "ui/model/workbench_context.h"
#include "ui/widgets/flow_row.h"

namespace lmc::ui {

std::unique_ptr<Tab> make_review_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<ReviewTab>(status, context);
}

ReviewTab::ReviewTab(StatusSink& status, WorkbenchContext& context)
    : status_(status),
      context_(context),
      state_(std::make_shared<ReviewState>()),
      welcome_(state_),
      open_(state_),
      export_panel_(state_),
      sources_(state_),
      table_(state_),
      trial_view_(state_),
      agreement_(state_),
      study_tables_(state_) {
  take_review_requests();
}

void ReviewTab::update(bool /*shown*/) {
  take_review_requests();
  state_->update();
  context_.review_folders() = state_->folders();
  // Jobs end on their workers whenever they end: compare with the last frame, not within this one.
  const MotionExportJob& export_job = state_->motion_export();
  if (job_finished(export_job.state()) && export_job.runs() != reported_exports_) {
    reported_exports_ = export_job.runs();
    report_export();
  }
  // Each new batch is reported once, when it is taken: a batch can begin and end between two
  // frames (a second folder from the cache), and its count must replace the first folder's.
  const ReviewBatch* b = state_->batch();
  if (b != nullptr && b != reported_batch_ && !state_->batch_job().running()) {
    reported_batch_ = b;
    status_.set_status("Review: " + std::to_string(b->trials.size()) + " trial(s) ready in " +
                       std::to_string(state_->folders().size()) + " folder(s) (" + std::to_string(b->from_cache) +
                       " from the cache)");
  }
}

void ReviewTab::draw() {
  if (state_->folders().empty()) {
    welcome_.draw();
    return;
  }
  // The top bar: what can be opened, Export..., then the fusion, what is open and the batch.
  open_.draw();
  ImGui::SameLine();
  export_panel_.draw_button();
  ImGui::SameLine();
  if (ImGui::Button("Design a layout for these trials")) design_layout_for_shown_trials();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Opens the Layout tab with the trials the table shows as its pose set (their fused hands)");
  // The fusion and the open folders go on a line of their own when the window is narrow (after
  // scripts/run the demo's button makes the row too wide for a 1024-pixel screen).
  same_line_or_wrap(ReviewSourcesPanel::fusion_width(), 20);
  sources_.draw();
  ImGui::Separator();
  table_.draw();
  if (ImGui::BeginTabBar("review_views")) {
    if (ImGui::BeginTabItem("Trial against Vicon", nullptr,
                            pending_view_ == ReviewView::kTrial ? ImGuiTabItemFlags_SetSelected : 0)) {
      trial_view_.draw(context_.picture_renderer());
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Agreement", nullptr,
                            pending_view_ == ReviewView::kAgreement ? ImGuiTabItemFlags_SetSelected : 0)) {
      agreement_.draw(context_.picture_renderer());
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Study tables", nullptr,
                            pending_view_ == ReviewView::kStudyTables ? ImGuiTabItemFlags_SetSelected : 0)) {
      study_tables_.draw();
      ImGui::EndTabItem();
    }
    pending_view_.reset();
    ImGui::EndTabBar();
  }
  export_panel_.draw_window();
}

// The status bar's line for a finished export (the window may have been closed meanwhile).
void ReviewTab::report_export() {
  const MotionExportJob& job = state_->motion_export();
  if (job.state() == JobState::kFailed) {
    const std::string error = job.error();
    status_.set_status("Review: export failed: " + error.substr(0, error.find('\n')), true);  // its first line
  } else if (const auto o = job.outcome()) {
    status_.set_status(std::string("Review: ") + (o->cancelled ? "export cancelled after " : "exported ") +
                       std::to_string(o->trials) + " trial(s) to " + o->folder.string());
  }
}

// The trials the table shows, as the Layout tab's pose set: their LMC files, fused there.
void ReviewTab::design_layout_for_shown_trials() {
  std::vector<std::string> files;
  for (const int i : state_->visible_trials())
    files.push_back(state_->trials()[static_cast<size_t>(i)].job.lmc.string());
  if (files.empty()) {
    status_.set_status("Review: no trials shown to design a layout for", true);
    return;
  }
  status_.set_status("Layout: designing for " + std::to_string(files.size()) + " trial(s) from Review");
  context_.layout_pose_request() = std::move(files);
  context_.tab_request() = "layout";
}

// Folders other parts of the workbench asked to review (start-up, the Record tab): one run.
void ReviewTab::take_review_requests() {
  auto& requests = context_.review_requests();
  if (requests.empty()) return;
  state_->open_folders(requests);
  requests.clear();
  // A folder that is not there is said where it is read first, not in a tooltip.
  if (state_->problem().rfind("not opened: ", 0) == 0) status_.set_status("Review: " + state_->problem(), true);
}

}  // namespace lmc::ui
