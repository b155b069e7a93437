// The subject screen's monitor: a second monitor when there is one, the operator's pick (kept by
// name between sessions), back on what is left when its monitor is unplugged.
#include <gtest/gtest.h>

#include "ui/model/record/subject_screen_monitor.h"

namespace lmc::ui {
namespace subject_screen_monitor_test {  // named: test files share unity batches

const Monitor kLaptop{"eDP-1", {0, 0, 1920, 1080}, true};
const Monitor kProjector{"HDMI-1", {1920, 0, 1280, 800}, false};
const Monitor kSideScreen{"DP-2", {-1280, 0, 1280, 1024}, false};
const ScreenRect kWorkbench{0, 0, 1280, 800};

TEST(SubjectScreenMonitor, OpensOnASecondMonitorWhenThereIsOne) {
  EXPECT_EQ(choose_subject_monitor({kLaptop, kProjector}, -1, std::nullopt), 1);
  // GLFW lists the primary first, but the rule reads the flag, not the order.
  EXPECT_EQ(choose_subject_monitor({kProjector, kLaptop}, -1, std::nullopt), 0);
  // Three: the first that is not the primary.
  EXPECT_EQ(choose_subject_monitor({kLaptop, kSideScreen, kProjector}, -1, std::nullopt), 1);
  // One: that one (the window goes beside the workbench, below); none: none.
  EXPECT_EQ(choose_subject_monitor({kLaptop}, -1, std::nullopt), 0);
  EXPECT_EQ(choose_subject_monitor({}, -1, std::nullopt), -1);
}

TEST(SubjectScreenMonitor, TheOperatorsPickWinsThenTheSavedOneByName) {
  const std::vector<Monitor> three = {kLaptop, kSideScreen, kProjector};
  EXPECT_EQ(choose_subject_monitor(three, 2, std::nullopt), 2);
  EXPECT_EQ(choose_subject_monitor(three, 0, kProjector), 0);   // this session's pick over the saved one
  EXPECT_EQ(choose_subject_monitor(three, -1, kProjector), 2);  // saved last session
  EXPECT_EQ(choose_subject_monitor(three, 7, kProjector), 2);   // a stale index counts as no pick
  // The projector now plugged in at another place: still found by its name.
  Monitor moved = kProjector;
  moved.rect.x = -1280;
  EXPECT_EQ(choose_subject_monitor({kLaptop, moved}, -1, kProjector), 1);
  // Saved but not connected: the bench's default.
  EXPECT_EQ(choose_subject_monitor({kLaptop, kSideScreen}, -1, kProjector), 1);
}

TEST(SubjectScreenMonitor, TwoMonitorsOfOneNameAreToldApartByPlace) {
  // Windows names most monitors "Generic PnP Monitor".
  const Monitor a{"Generic PnP Monitor", {0, 0, 1920, 1080}, true};
  const Monitor b{"Generic PnP Monitor", {1920, 0, 1920, 1080}, false};
  EXPECT_EQ(find_monitor({a, b}, b), 1);
  EXPECT_EQ(find_monitor({a, b}, a), 0);
  Monitor elsewhere = b;
  elsewhere.rect.x = 5000;
  EXPECT_EQ(find_monitor({a, b}, elsewhere), -1);  // ambiguous: not guessed
  EXPECT_EQ(find_monitor({a}, elsewhere), 0);      // the only one of that name
}

TEST(SubjectScreenMonitor, CoversTheChosenMonitorOrOpensAWindowBesideTheWorkbench) {
  const SubjectScreenPlace covering = place_subject_screen({kLaptop, kProjector}, 1, false, kWorkbench, std::nullopt);
  EXPECT_TRUE(covering.covers_monitor);
  EXPECT_EQ(covering.monitor, 1);
  EXPECT_EQ(covering.rect, kProjector.rect);
  // Windowed on the projector: a window on it, not over the whole of it.
  const SubjectScreenPlace window = place_subject_screen({kLaptop, kProjector}, 1, true, kWorkbench, std::nullopt);
  EXPECT_FALSE(window.covers_monitor);
  EXPECT_GE(window.rect.x, kProjector.rect.x);
  EXPECT_LT(window.rect.width, kProjector.rect.width);
  // One monitor: beside the workbench (subject_window_rect), or where the operator left it.
  const SubjectScreenPlace beside = place_subject_screen({kLaptop}, 0, true, kWorkbench, std::nullopt);
  EXPECT_FALSE(beside.covers_monitor);
  EXPECT_GE(beside.rect.x, kWorkbench.width);
  const ScreenRect left_there{100, 500, 700, 440};
  EXPECT_EQ(place_subject_screen({kLaptop}, 0, true, kWorkbench, left_there).rect, left_there);
  // No monitor known: a window all the same.
  EXPECT_FALSE(place_subject_screen({}, -1, false, kWorkbench, std::nullopt).covers_monitor);
}

TEST(SubjectScreenMonitor, UnpluggingItsMonitorPlacesItAgainOnWhatIsLeft) {
  EXPECT_FALSE(subject_monitor_gone({kLaptop, kProjector}, kProjector));
  EXPECT_TRUE(subject_monitor_gone({kLaptop}, kProjector));
  // What the window does then: the same rule on the monitors left — the laptop alone, so a
  // window beside the workbench, not a cover over the operator's own screen.
  const int monitor = choose_subject_monitor({kLaptop}, -1, kProjector);
  EXPECT_EQ(monitor, 0);
  const SubjectScreenPlace back = place_subject_screen({kLaptop}, monitor, true, kWorkbench, std::nullopt);
  EXPECT_FALSE(back.covers_monitor);
  EXPECT_LE(back.rect.x + back.rect.width, kLaptop.rect.width);
  // A monitor that moved counts as gone too: the window is placed again where it now is.
  Monitor moved = kProjector;
  moved.rect.x = -1280;
  EXPECT_TRUE(subject_monitor_gone({kLaptop, moved}, kProjector));
}

TEST(SubjectScreenMonitor, TheSettingsFileKeepsTheWindowAndTheMonitor) {
  SubjectScreenSettings settings;
  settings.window = ScreenRect{100, 500, 700, 440};
  settings.monitor = Monitor{"Generic PnP Monitor", {1920, 0, 1920, 1080}, false};
  const std::string text = subject_screen_settings_text(settings);
  EXPECT_EQ(text, "100 500 700 440\nmonitor 1920 0 1920 1080 Generic PnP Monitor\n");
  EXPECT_EQ(parse_subject_screen_settings(text), settings);
  // The file as earlier versions wrote it (the window's line only) still reads.
  EXPECT_EQ(parse_subject_screen_settings("100 500 700 440\n").window, settings.window);
  EXPECT_FALSE(parse_subject_screen_settings("100 500 700 440\n").monitor.has_value());
  // CRLF (edited on Windows) and damaged lines.
  EXPECT_EQ(parse_subject_screen_settings("100 500 700 440\r\nmonitor 1920 0 1920 1080 HDMI-1\r\n").monitor->name,
            "HDMI-1");
  const SubjectScreenSettings damaged = parse_subject_screen_settings("wide\nmonitor 1 2 three\nmonitor 0 0 0 0 X\n");
  EXPECT_FALSE(damaged.window.has_value());
  EXPECT_FALSE(damaged.monitor.has_value());
}

TEST(SubjectScreenMonitor, LabelsSayWhichIsThePrimary) {
  EXPECT_EQ(monitor_label(kLaptop), "eDP-1 (1920x1080, primary)");
  EXPECT_EQ(monitor_label(kProjector), "HDMI-1 (1280x800)");
  EXPECT_EQ(monitor_label(Monitor{"", {0, 0, 800, 600}, false}), "monitor (800x600)");
  // The closed dropdown: no name (Windows' "Generic Non-PnP Monitor" did not fit its box).
  EXPECT_EQ(monitor_short_label(0, Monitor{"Generic Non-PnP Monitor", {0, 0, 1920, 1080}, true}),
            "1: 1920x1080, primary");
  EXPECT_EQ(monitor_short_label(1, kProjector), "2: 1280x800");
}

}  // namespace subject_screen_monitor_test
}  // namespace lmc::ui
