#pragma once
// Help → Help (F1): how to design a first layout, every keyboard shortcut, and About. The
// shortcut list is data so the window and its test read the same rows.
#include <string>
#include <vector>

namespace lmc::ui {

struct ShortcutRow {
  std::string where;  // "Everywhere", "Layout", "Record"
  std::string keys;   // "Ctrl+S"
  std::string does;
};

// Every shortcut the workbench handles (kept beside the code that handles them: grep
// IsKeyPressed under ui/ when adding one).
const std::vector<ShortcutRow>& shortcut_rows();

class HelpWindow {
 public:
  enum class Section { kWalkthrough, kShortcuts, kAbout };
  void open(Section section = Section::kWalkthrough) {
    open_ = true;
    select_ = section;
    select_pending_ = true;
  }
  bool is_open() const { return open_; }
  // Draws the window while open (a top-level window, outside the shell's full-screen one).
  void draw();

 private:
  bool open_ = false;
  bool select_pending_ = false;
  Section select_ = Section::kWalkthrough;
};

}  // namespace lmc::ui
