// The capture scripts (ui/app/capture/) stage a tab through its public actions only: the Layout
// script on a headless Layout tab, the Record script on a Record tab of the workbench's context.
#include "ui/app/capture/tab_capture.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/ui/headless_imgui.h"
#include "tests/ui/last_status.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/tabs/record/record_tab.h"

namespace lmc::ui {
namespace {

using testing::HeadlessImGui;

TEST(LayoutCapture, StagesTheStartLayoutAndTakesTheMixedRigBackWhenAnotherTabIsShown) {
  HeadlessImGui gui;
  testing::LastStatus status;
  WorkbenchContext context;
  LayoutTab tab(status);
  tab.set_modals_enabled(false);
  const auto script = make_tab_capture(tab, context);
  EXPECT_EQ(script->prepare(), 4);
  EXPECT_EQ(tab.state().layout().name, LayoutTab::kStartLayout);
  EXPECT_EQ(tab.state().selected(), 1);
  EXPECT_EQ(tab.state().display.heatmap_finger, 1) << "the index finger's heatmap";
  EXPECT_EQ(script->extra_captures(), std::vector<std::string>{"layout-mixed-rig"});

  const size_t steps = tab.state().history().undo_size();
  script->prepare_extra("layout-mixed-rig");
  EXPECT_EQ(tab.state().layout().devices[2].model, "lmc2");
  EXPECT_EQ(tab.state().layout().devices[3].model, "lmc2");
  EXPECT_EQ(tab.state().selected(), 2) << "the first LMC2, its model in the Inspector";
  script->before_frame(true);
  EXPECT_EQ(tab.state().layout().devices[2].model, "lmc2") << "kept while the Layout tab is shown";
  script->before_frame(false);
  EXPECT_EQ(tab.state().history().undo_size(), steps) << "taken back once another tab is shown";
  EXPECT_NE(tab.state().layout().devices[2].model, "lmc2");
}

TEST(RecordCapture, FillsTheSetUpFormLastAndStopsDrivingTheSession) {
  HeadlessImGui gui;
  testing::LastStatus status;
  WorkbenchContext context;
  const std::unique_ptr<Tab> tab = make_record_tab(status, context);
  const auto script = make_tab_capture(*tab, context);
  script->prepare();
  EXPECT_TRUE(context.subject_screen().open) << "the subject screen is pictured too";
  EXPECT_TRUE(script->busy()) << "waits for the second trial to be under way";
  script->prepare_extra("record-setup");
  EXPECT_FALSE(script->busy());
  auto& record = dynamic_cast<RecordTab&>(*tab);
  EXPECT_FALSE(record.model().has_session());
  EXPECT_EQ(std::string(record.form().subject), "S07");
  script->after_frame(true);
  EXPECT_FALSE(record.model().has_session()) << "no session is created once the form is shown";
}

}  // namespace
}  // namespace lmc::ui
