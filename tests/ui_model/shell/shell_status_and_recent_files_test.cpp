// The shell's per-tab status lines and the File menu's recent-files list: plain logic, no ImGui.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/reference_data.h"
#include "ui/model/shell/recent_files.h"
#include "ui/model/shell/status_board.h"

namespace lmc::ui {
namespace shell_status_recent_test {

std::filesystem::path touch(const std::filesystem::path& p) {
  std::ofstream(p) << "{}";
  return p;
}

TEST(StatusBoard, AMessageStaysWithTheTabThatRaisedIt) {
  StatusBoard board;
  board.post("layout", "Cannot open layout: bad JSON", true);
  EXPECT_TRUE(board.shown("layout").is_error);
  EXPECT_EQ(board.shown("layout").text, "Cannot open layout: bad JSON");
  const StatusLine devices = board.shown("devices");
  EXPECT_FALSE(devices.is_error) << "a layout error must not stay red on the Devices tab";
  EXPECT_EQ(devices.text, "Ready.");
  board.post("devices", "no controller found: running the simulated rig", false);
  EXPECT_EQ(board.shown("devices").text, "no controller found: running the simulated rig");
  EXPECT_TRUE(board.shown("layout").is_error) << "the layout error is still there when the user comes back";
  EXPECT_LT(board.latest("layout")->sequence, board.latest("devices")->sequence);
  EXPECT_FALSE(board.latest("record").has_value());
}

TEST(StatusBoard, TheNewcomerHintShowsUntilTheFirstActionButNeverHidesAnError) {
  StatusBoard board("Start here");
  EXPECT_TRUE(board.shown("layout").is_hint);
  board.post("layout", "Opened x.json", false);
  EXPECT_EQ(board.shown("layout").text, "Start here") << "routine start-up messages do not push the hint away";
  board.post("devices", "LeapC failed", true);
  EXPECT_EQ(board.shown("devices").text, "LeapC failed");
  board.dismiss_hint();
  EXPECT_FALSE(board.hint_showing());
  EXPECT_EQ(board.shown("layout").text, "Opened x.json");
  EXPECT_EQ(board.shown("review").text, "Ready.");
}

TEST(RecentFiles, NewestFirstWithoutDuplicatesAndBounded) {
  RecentFiles r(3);
  EXPECT_TRUE(r.add("/tmp/a.json", "layout"));
  EXPECT_TRUE(r.add("/tmp/b.json", "layout"));
  EXPECT_FALSE(r.add("/tmp/b.json", "layout")) << "already first: nothing changes";
  EXPECT_TRUE(r.add("/tmp/x/../a.json", "layout")) << "another spelling of a.json moves it to the front";
  ASSERT_EQ(r.entries().size(), 2u);
  EXPECT_EQ(r.entries()[0].path, "/tmp/a.json");
  EXPECT_EQ(r.entries()[1].path, "/tmp/b.json");
  r.add("/tmp/c.json", "layout");
  r.add("/tmp/d.json", "layout");
  ASSERT_EQ(r.entries().size(), 3u);
  EXPECT_EQ(r.entries()[0].path, "/tmp/d.json");
  EXPECT_EQ(r.entries()[2].path, "/tmp/a.json") << "the oldest (b) fell off";
  r.remove("/tmp/c.json");
  EXPECT_EQ(r.entries().size(), 2u);
}

TEST(RecentFiles, RoundTripsThroughItsFileAndKeepsMissingEntries) {
  const auto dir = test::scratch_dir("shell_recent_files");
  const auto kept = touch(dir / "kept.json");
  RecentFiles r;
  r.add(dir / "gone.json", "layout");  // never existed: the menu shows it disabled, it is not dropped
  r.add(kept, "layout");
  const auto file = dir / "config" / "recent_files.json";
  std::filesystem::create_directories(file.parent_path());
  EXPECT_EQ(r.save(file), "");
  const RecentFiles back = RecentFiles::load(file);
  EXPECT_EQ(back.entries(), r.entries());
  EXPECT_EQ(back.entries()[0].kind, "layout");
}

TEST(RecentFiles, AMissingOrDamagedFileIsAnEmptyList) {
  const auto dir = test::scratch_dir("shell_recent_files_bad");
  EXPECT_TRUE(RecentFiles::load(dir / "none.json").entries().empty());
  std::ofstream(dir / "bad.json") << "{ not json";
  EXPECT_TRUE(RecentFiles::load(dir / "bad.json").entries().empty());
  const RecentFiles partly = RecentFiles::from_json(
      R"({"recent_files": [{"path": "/tmp/ok.json", "kind": "layout"}, {"path": 3}, "x", {"path": "/tmp/ok.json"}]})");
  ASSERT_EQ(partly.entries().size(), 1u) << "malformed and repeated entries are skipped";
  EXPECT_EQ(partly.entries()[0].path, "/tmp/ok.json");
  EXPECT_EQ(RecentFiles().save(dir / "no_such_folder" / "r.json").empty(), false) << "an unwritable place is reported";
}

}  // namespace shell_status_recent_test
}  // namespace lmc::ui
