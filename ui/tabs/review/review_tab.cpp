// The Review tab: the folders a researcher opened, processed in the background into one table
// of trials, the selected trial against Vicon with its 3D replay, agreement across the trials shown
// and the study's tables, and exports. Its state is ui/model/review/review_state.h; the panels
// beside this file draw it (open buttons, Export..., sources bar, trial table, trial view with the
// replay, agreement, study tables, the welcome shown while nothing is open) and this file lays them
// out, reports finished work on the status bar and sets up the --capture pictures.
#include "ui/tabs/review/review_tab.h"

#include <imgui.h>

#include <cstdlib>
#include <memory>

#include "core/review/review_figures.h"
#include "ui/model/review/review_state.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/review/review_agreement_panel.h"
#include "ui/tabs/review/review_export_panel.h"
#include "ui/tabs/review/review_open_panel.h"
#include "ui/tabs/review/review_sources_panel.h"
#include "ui/tabs/review/review_study_tables_panel.h"
#include "ui/tabs/review/review_trial_table_panel.h"
#include "ui/tabs/review/review_trial_view_panel.h"
#include "ui/tabs/review/review_welcome_panel.h"
#include "ui/widgets/figure_view.h"
#include "ui/widgets/flow_row.h"

namespace lmc::ui {
namespace {

class ReviewTab final : public Tab {
 public:
  ReviewTab(StatusSink& status, WorkbenchContext& context)
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

  void update(bool /*shown*/) override {
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

  void draw() override {
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
      if (ImGui::BeginTabItem("Trial against Vicon", nullptr, pending_view_ == 0 ? ImGuiTabItemFlags_SetSelected : 0)) {
        trial_view_.draw(context_.picture_renderer());
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Agreement", nullptr, pending_view_ == 1 ? ImGuiTabItemFlags_SetSelected : 0)) {
        agreement_.draw(context_.picture_renderer());
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Study tables", nullptr, pending_view_ == 2 ? ImGuiTabItemFlags_SetSelected : 0)) {
        study_tables_.draw();
        ImGui::EndTabItem();
      }
      pending_view_ = -1;
      ImGui::EndTabBar();
    }
    export_panel_.draw_window();
  }

  // The status bar's line for a finished export (the window may have been closed meanwhile).
  void report_export() {
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
  void design_layout_for_shown_trials() {
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
  void take_review_requests() {
    auto& requests = context_.review_requests();
    if (requests.empty()) return;
    state_->open_folders(requests);
    requests.clear();
    // A folder that is not there is said where it is read first, not in a tooltip.
    if (state_->problem().rfind("not opened: ", 0) == 0) status_.set_status("Review: " + state_->problem(), true);
  }

  int prepare_for_capture() override {
    pending_view_ = 0;
    if (const char* trial = std::getenv("LMC_REVIEW_TRIAL"); trial != nullptr && *trial != '\0')
      state_->prefer_trial(trial);
    // LMC_REVIEW_LENGTH_CORRECTION=FILE: the first opened folder's trials with that subject's
    // finger-length correction (the picture shows the chip and the corrected lengths).
    if (const char* file = std::getenv("LMC_REVIEW_LENGTH_CORRECTION");
        file != nullptr && *file != '\0' && !state_->folders().empty()) {
      state_->set_length_correction(state_->folders().front(), file);
    }
    return 4;
  }
  bool busy_for_capture() const override { return state_->busy(); }
  std::vector<std::string> extra_captures() const override {
    std::vector<std::string> names{"review-agreement", "review-study-tables", "review-export"};
    // LMC_REVIEW_EXPORT_DIR=DIR: the trials shown are exported there as C3D and the finished
    // window is pictured too (the smoke test checks the files).
    if (const char* dir = std::getenv("LMC_REVIEW_EXPORT_DIR"); dir != nullptr && *dir != '\0')
      names.push_back("review-export-done");
    return names;
  }
  void prepare_extra_capture(const std::string& name) override {
    if (name == "review-agreement") {
      pending_view_ = 1;
      // LMC_REVIEW_PNG=FILE: the pooled group's first Bland-Altman figure is also saved as a PNG
      // through the off-screen renderer, so the smoke test checks the PNG export end to end.
      const char* png = std::getenv("LMC_REVIEW_PNG");
      const auto& groups = state_->agreement().table.groups;
      if (png != nullptr && *png != '\0' && context_.picture_renderer() && !groups.empty() &&
          !groups.back().measures.empty()) {
        const Figure figure = bland_altman_figure(groups.back(), groups.back().measures.front());
        context_.picture_renderer()(1000, 700, png, [&figure] { draw_figure_filling("ba", figure); });
      }
    }
    if (name == "review-study-tables") pending_view_ = 2;
    if (name == "review-export") {
      pending_view_ = 0;
      export_panel_.open();
      export_panel_.choose(ReviewExportPanel::What::kShown);
    }
    if (name == "review-export-done") {
      export_panel_.set_folder(std::getenv("LMC_REVIEW_EXPORT_DIR"));
      export_panel_.start();
    }
  }

 private:
  StatusSink& status_;
  WorkbenchContext& context_;
  std::shared_ptr<ReviewState> state_;  // shared with every panel
  ReviewWelcomePanel welcome_;
  ReviewOpenPanel open_;
  ReviewExportPanel export_panel_;
  ReviewSourcesPanel sources_;
  ReviewTrialTablePanel table_;
  ReviewTrialViewPanel trial_view_;
  ReviewAgreementPanel agreement_;
  ReviewStudyTablesPanel study_tables_;
  const ReviewBatch* reported_batch_ = nullptr;  // the batch whose count the status line gave
  int reported_exports_ = 0;                     // the export runs whose outcome the status bar has shown
  int pending_view_ = -1;                        // a capture's request: 0 the trial view, 1 agreement, 2 study tables
};

}  // namespace

std::unique_ptr<Tab> make_review_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<ReviewTab>(status, context);
}

}  // namespace lmc::ui
