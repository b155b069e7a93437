#pragma once
// The Review tab (review_tab.cpp says what it shows): the composition root of its state and
// panels.
#include <memory>
#include <optional>

#include "ui/model/review/review_state.h"
#include "ui/tabs/review/review_agreement_panel.h"
#include "ui/tabs/review/review_export_panel.h"
#include "ui/tabs/review/review_open_panel.h"
#include "ui/tabs/review/review_sources_panel.h"
#include "ui/tabs/review/review_study_tables_panel.h"
#include "ui/tabs/review/review_trial_table_panel.h"
#include "ui/tabs/review/review_trial_view_panel.h"
#include "ui/tabs/review/review_welcome_panel.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

class WorkbenchContext;

std::unique_ptr<Tab> make_review_tab(StatusSink& status, WorkbenchContext& context);

// The views under the trial table.
enum class ReviewView { kTrial, kAgreement, kStudyTables };

class ReviewTab final : public Tab {
 public:
  ReviewTab(StatusSink& status, WorkbenchContext& context);

  void update(bool shown) override;
  void draw() override;

  // ---- what a script may drive (--capture) --------------------------------------------------
  ReviewState& state() { return *state_; }
  ReviewExportPanel& export_panel() { return export_panel_; }
  // Brings a view to the front on the next draw.
  void show_view(ReviewView view) { pending_view_ = view; }

 private:
  void report_export();
  void design_layout_for_shown_trials();
  void take_review_requests();

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
  std::optional<ReviewView> pending_view_;       // show_view()'s, for the next draw
};

}  // namespace lmc::ui
