// Headless tests of the shell's pieces: per-tab status sinks, the Help window and its shortcut
// table, the split-panel widget, the File-menu interface of the Layout tab and the Inspector's
// single-click typing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/io/layout_json.h"
#include "tests/support/reference_data.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/last_status.h"
#include "ui/app/help_window.h"
#include "ui/app/tab_status_sink.h"
#include "ui/app/workbench_shell.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/tabs/layout/inspector_panel.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/widgets/split_panels.h"

namespace lmc::ui {
namespace shell_pieces_test {

using testing::HeadlessImGui;

TEST(TabStatusSink, EachTabsMessagesAreFiledUnderItsOwnId) {
  StatusBoard board;
  TabStatusSink layout(board, "layout");
  TabStatusSink devices(board, "devices");
  StatusSink& as_tab_sees_it = layout;
  as_tab_sees_it.set_status("Cannot open layout: $.devices[0]: missing", true);
  devices.set_status("rig running", false);
  EXPECT_TRUE(board.shown("layout").is_error);
  EXPECT_EQ(board.shown("devices").text, "rig running");
  EXPECT_FALSE(board.shown("devices").is_error);
}

TEST(HelpWindow, ListsEveryShortcutTheCodeHandles) {
  const auto& rows = shortcut_rows();
  const auto has = [&](const std::string& where, const std::string& keys) {
    return std::any_of(rows.begin(), rows.end(),
                       [&](const ShortcutRow& r) { return r.where == where && r.keys == keys; });
  };
  EXPECT_TRUE(has("Everywhere", "F1"));
  EXPECT_TRUE(has("Everywhere", "Ctrl+Q"));
  for (const char* k : {"Ctrl+N", "Ctrl+O", "Ctrl+S", "Ctrl+Shift+S", "Ctrl+Z", "F", "Esc", "Delete"}) {
    EXPECT_TRUE(has("Layout", k)) << k;
  }
  for (const char* k : {"Space", "Enter", "R"}) EXPECT_TRUE(has("Record", k)) << k;
  EXPECT_TRUE(has("Devices", "Ctrl+Z"));
}

TEST(HelpWindow, DrawsEachSectionWhenOpenAndNothingWhenClosed) {
  HeadlessImGui gui;
  HelpWindow help;
  const auto frame = [&] {
    ImGui::NewFrame();
    help.draw();
    ImGui::Render();
  };
  frame();
  EXPECT_EQ(ImGui::GetDrawData()->CmdListsCount, 0) << "closed: nothing drawn";
  for (auto section :
       {HelpWindow::Section::kWalkthrough, HelpWindow::Section::kShortcuts, HelpWindow::Section::kAbout}) {
    help.open(section);
    frame();
    frame();
    EXPECT_TRUE(help.is_open());
    EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, 100);
  }
}

TEST(SplitPanels, TheSplitterResizesTheRightPanelWithinItsLimits) {
  HeadlessImGui gui{1000, 600};
  SplitPanels split(400.0f);
  ImVec2 right_min{};
  const auto body = [&] {
    split.draw([] { ImGui::TextUnformatted("left"); }, [&] { right_min = ImGui::GetWindowPos(); });
  };
  gui.frames(2, body);
  EXPECT_FLOAT_EQ(split.right_width(), 400.0f);
  // The splitter sits just left of the right panel; drag it 100 px left: the right panel grows.
  const float splitter_x = right_min.x - 3.0f;
  gui.drag(ImVec2(splitter_x, 300), ImVec2(splitter_x - 100, 300), 5, body);
  EXPECT_NEAR(split.right_width(), 500.0f, 1.0f);
  gui.drag(ImVec2(right_min.x - 3.0f, 300), ImVec2(5, 300), 5, body);
  gui.frame(body);
  EXPECT_LE(split.right_width(), ImGui::GetIO().DisplaySize.x - 300.0f + 1.0f) << "the left side keeps its minimum";
  gui.drag(ImVec2(right_min.x - 3.0f, 300), ImVec2(995, 300), 5, body);
  gui.frame(body);
  EXPECT_FLOAT_EQ(split.right_width(), 320.0f) << "the right side keeps its minimum";
}

using QuietStatus = lmc::ui::testing::LastStatus;

TEST(LayoutTabFileCommands, TheShellsCommandsRunTheTabsOwnOpenAndSave) {
  HeadlessImGui gui;
  QuietStatus status;
  LayoutTab tab(status);
  tab.set_modals_enabled(false);
  EXPECT_EQ(tab.document_kind(), "layout");
  EXPECT_FALSE(tab.document_path().has_value()) << "a preset has no file";

  const auto dir = test::scratch_dir("shell_layout_file_commands");
  const auto file = dir / "mine.json";
  save_layout(default_new_layout(), file);
  tab.open_document(file);
  ASSERT_TRUE(tab.document_path().has_value()) << status.last;
  EXPECT_EQ(*tab.document_path(), file);
  EXPECT_EQ(tab.state().layout().device_count(), default_new_layout().device_count());

  // Save with a file: writes it straight away, no dialog.
  ASSERT_TRUE(tab.state().report(add_device(tab.state().upd_history()), "Add"));
  EXPECT_TRUE(tab.has_unsaved_changes());
  tab.handle_file_command(FileCommand::kSave);
  EXPECT_FALSE(tab.has_unsaved_changes());
  EXPECT_EQ(load_layout(file).device_count(), default_new_layout().device_count() + 1);

  // New replaces the document (no modal in tests) and forgets the file.
  tab.handle_file_command(FileCommand::kNew);
  EXPECT_EQ(status.last, "New layout");
}

TEST(InspectorTyping, ASingleClickOnAPoseFieldStartsTyping) {
  HeadlessImGui gui{700, 900};
  auto state = std::make_shared<LayoutState>(make_document(default_new_layout()));
  state->select(0);
  InspectorPanel inspector{state};
  const auto body = [&] { inspector.draw(); };
  gui.frame(body);
  const auto c = inspector.anchors().centre("pose.0");
  ASSERT_TRUE(c.has_value());
  gui.click(c->x, c->y, body);
  gui.frames(3, body);  // the focus request lands one frame later, text input the next
  EXPECT_TRUE(ImGui::GetIO().WantTextInput) << "one click, no drag: the field takes typing";
  EXPECT_EQ(state->history().undo_size(), 0u) << "a click alone changes nothing";
}

TEST(WorkbenchShellHeadless, OpenedOnASessionOrFoldersToReviewItShowsNoNewcomersHint) {
  HeadlessImGui gui;
  const auto dir = test::scratch_dir("shell_headless_task");
  ShellStartup on_session;
  on_session.record = RecordStartup{};
  on_session.record->session = dir / "no-such-session";
  WorkbenchShell a(std::move(on_session));
  EXPECT_FALSE(a.status_board().hint_showing()) << "--session: the Record tab speaks, not 'Start here'";
  ShellStartup on_review;
  on_review.review = {dir};
  WorkbenchShell b(std::move(on_review));
  EXPECT_FALSE(b.status_board().hint_showing());
  WorkbenchShell c{ShellStartup{}};
  EXPECT_TRUE(c.status_board().hint_showing()) << "a plain start keeps the hint";
}

TEST(WorkbenchShellHeadless, TracksRecentFilesAndDropsTheHintOnTheFirstClick) {
  HeadlessImGui gui;
  const auto dir = test::scratch_dir("shell_headless_recent");
  ShellStartup startup;
  startup.recent_files_path = dir / "recent_files.json";
  WorkbenchShell shell(std::move(startup));
  const auto frame = [&] {
    ImGui::NewFrame();
    shell.frame();
    ImGui::Render();
  };
  frame();
  EXPECT_TRUE(shell.status_board().shown(shell.active_tab_id()).is_hint);
  EXPECT_TRUE(shell.recent_files().entries().empty());

  const auto file = dir / "mine.json";
  save_layout(default_new_layout(), file);
  ASSERT_EQ(shell.tab(0).document_kind(), "layout");
  shell.tab(0).open_document(file);
  frame();
  ASSERT_EQ(shell.recent_files().entries().size(), 1u) << "a file the tab opened joins the recent list";
  EXPECT_EQ(shell.recent_files().entries()[0].kind, "layout");
  EXPECT_EQ(RecentFiles::load(dir / "recent_files.json").entries(), shell.recent_files().entries());

  gui.move_to(640, 400);
  gui.set_button(0, true);
  frame();
  gui.set_button(0, false);
  frame();
  EXPECT_FALSE(shell.status_board().hint_showing()) << "the first click ends the newcomer's hint";
  ASSERT_TRUE(shell.status_board().latest("layout").has_value());
  EXPECT_EQ(shell.status_board().shown("layout").text, "Opened " + file.string());
  EXPECT_NE(shell.status_board().shown("review").text, "Opened " + file.string()) << "not on another tab";
}

}  // namespace shell_pieces_test
}  // namespace lmc::ui
