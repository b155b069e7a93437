#pragma once
// What `--capture` does to a tab before its pictures: one script per tab, beside this file, that
// puts the tab in a representative state (a preset layout, a running simulated rig, a session
// recorded to mid-trial, processed trials) through the tab's public actions only, and reads the
// environment switches that pick what a picture shows. The tabs know nothing of captures.
#include <memory>
#include <string>
#include <vector>

namespace lmc::ui {

class Tab;
class WorkbenchContext;
class LayoutTab;
class DevicesTab;
class RecordTab;
class ReviewTab;

class TabCapture {
 public:
  virtual ~TabCapture() = default;
  // Before the tab's first picture: returns the frames to wait.
  virtual int prepare() { return 2; }
  // True while the tab's background work should be allowed to finish before a picture.
  virtual bool busy() const { return false; }
  // More pictures of this tab after its own, in order (file names without ".png"); a name
  // starting "subject-screen" is taken from the subject screen's window.
  virtual std::vector<std::string> extra_captures() const { return {}; }
  // Moves the tab towards extra picture `name`; the capture then waits while busy().
  virtual void prepare_extra(const std::string& /*name*/) {}
  // Around every frame the capture draws, for every script made so far; `shown`: its tab is the
  // one on screen.
  virtual void before_frame(bool /*shown*/) {}
  virtual void after_frame(bool /*shown*/) {}
  // When the process ends (the shell and its tabs still alive): what a script reports.
  virtual void finish() {}
};

// The script for `tab` (one of the registry's); a script that does nothing for a tab it does not know.
std::unique_ptr<TabCapture> make_tab_capture(Tab& tab, WorkbenchContext& context);

std::unique_ptr<TabCapture> make_layout_capture(LayoutTab& tab);
std::unique_ptr<TabCapture> make_devices_capture(DevicesTab& tab);
std::unique_ptr<TabCapture> make_record_capture(RecordTab& tab, WorkbenchContext& context);
std::unique_ptr<TabCapture> make_review_capture(ReviewTab& tab, WorkbenchContext& context);

}  // namespace lmc::ui
