#pragma once
// A workbench tab: one area of the product (Layout, Devices, Record, Review). The shell calls
// update() every frame before any drawing (poll jobs, drain device snapshots, refresh caches),
// then draw() inside the tab's region. draw() only emits ImGui calls.
#include <memory>
#include <string>

namespace lmc::ui {

class StatusSink;

class Tab {
 public:
  virtual ~Tab() = default;
  virtual void update() {}
  virtual void draw() = 0;
  // Text for the window title (e.g. the open layout file and an unsaved mark); empty for none.
  virtual std::string document_title() const { return {}; }
  // True when quitting would lose work; the shell then asks before closing.
  virtual bool has_unsaved_changes() const { return false; }
  // Called before a --capture screenshot so the tab shows representative content
  // (e.g. start the simulated rig, load the paper layout). Returns frames to wait.
  virtual int prepare_for_capture() { return 2; }
  // True while the tab's background work should be allowed to finish before a capture.
  virtual bool busy_for_capture() const { return false; }
};

// What tabs may tell the shell: one line in the status bar.
class StatusSink {
 public:
  virtual ~StatusSink() = default;
  virtual void set_status(const std::string& text, bool is_error = false) = 0;
};

}  // namespace lmc::ui
