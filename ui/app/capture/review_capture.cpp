// The Review tab's pictures: the trial view of what `--review` opened (LMC_REVIEW_TRIAL=NAME picks
// the trial; LMC_REVIEW_LENGTH_CORRECTION=FILE gives the first folder that subject's finger-length
// correction), then "review-agreement" (LMC_REVIEW_PNG=FILE also renders the pooled group's first
// Bland-Altman figure through the off-screen PNG path), "review-study-tables", "review-export" (the
// Export window) and, with LMC_REVIEW_EXPORT_DIR=DIR, "review-export-done" after the trials shown
// are exported there as C3D (the smoke test checks the files).
#include <cstdlib>
#include <string>
#include <vector>

#include "core/review/review_figures.h"
#include "ui/app/capture/tab_capture.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/review/review_tab.h"
#include "ui/widgets/figure_view.h"

namespace lmc::ui {
namespace {

const char* env_text(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? v : nullptr;
}

class ReviewCapture final : public TabCapture {
 public:
  ReviewCapture(ReviewTab& tab, WorkbenchContext& context) : tab_(tab), context_(context) {}

  int prepare() override {
    ReviewState& s = tab_.state();
    tab_.show_view(ReviewView::kTrial);
    if (const char* trial = env_text("LMC_REVIEW_TRIAL")) s.prefer_trial(trial);
    if (const char* file = env_text("LMC_REVIEW_LENGTH_CORRECTION"); file != nullptr && !s.folders().empty()) {
      s.set_length_correction(s.folders().front(), file);
    }
    return 4;
  }

  bool busy() const override { return tab_.state().busy(); }

  std::vector<std::string> extra_captures() const override {
    std::vector<std::string> names{"review-agreement", "review-study-tables", "review-export"};
    if (env_text("LMC_REVIEW_EXPORT_DIR") != nullptr) names.push_back("review-export-done");
    return names;
  }

  void prepare_extra(const std::string& name) override {
    if (name == "review-agreement") {
      tab_.show_view(ReviewView::kAgreement);
      if (const char* png = env_text("LMC_REVIEW_PNG")) render_bland_altman(png);
    }
    if (name == "review-study-tables") tab_.show_view(ReviewView::kStudyTables);
    if (name == "review-export") {
      tab_.show_view(ReviewView::kTrial);
      tab_.export_panel().open();
      tab_.export_panel().choose(ReviewExportPanel::What::kShown);
    }
    if (name == "review-export-done") {
      tab_.export_panel().set_folder(env_text("LMC_REVIEW_EXPORT_DIR"));
      tab_.export_panel().start();
    }
  }

 private:
  // The pooled group's first Bland-Altman figure as a PNG through the off-screen renderer.
  void render_bland_altman(const std::string& png) {
    const auto& groups = tab_.state().agreement().table.groups;
    if (!context_.picture_renderer() || groups.empty() || groups.back().measures.empty()) return;
    const Figure figure = bland_altman_figure(groups.back(), groups.back().measures.front());
    context_.picture_renderer()(1000, 700, png, [&figure] { draw_figure_filling("ba", figure); });
  }

  ReviewTab& tab_;
  WorkbenchContext& context_;
};

}  // namespace

std::unique_ptr<TabCapture> make_review_capture(ReviewTab& tab, WorkbenchContext& context) {
  return std::make_unique<ReviewCapture>(tab, context);
}

}  // namespace lmc::ui
