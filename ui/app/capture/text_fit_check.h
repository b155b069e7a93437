#pragma once
// Finds text a rendered frame does not show whole, for `--capture --check-text`: read from the
// frame's ImGui draw data, so it judges exactly what the picture shows, at any window size.
#include <string>
#include <vector>

namespace lmc::ui {

struct CutText {
  std::string window;  // the ImGui window that draws it ("Layout/##toolbar_AB12")
  std::string text;    // the words as drawn (an unreadable glyph as '?')
  std::string how;     // "cut at the right by its window", "ends in an ellipsis", "over 'X'", …
  int x = 0, y = 0;    // where, in window pixels
};

// The text of the frame ImGui rendered last (call after ImGui::Render(), before the next
// NewFrame) that is not shown whole:
// * a glyph cut by its window's edge, where the window cannot scroll that way;
// * a glyph cut on the right by its own widget's box (a label wider than its button or slider;
//   cut on the left only is a text field scrolled to show where typing goes on, and a file path
//   longer than its field is not reported either: the field scrolls).
// * a table header or tab ImGui shortened with an ellipsis;
// * a window whose content is wider than the window, with no horizontal scrollbar;
// * two lines of text drawn over each other in one window.
// ImGui leaves out a glyph wholly outside the clip rectangle, so text cut exactly between two
// letters by a box or a drawing's own clip shows nothing cut; the window-content rule catches it
// at a window's edge.
// An ellipsis the workbench writes itself (the status bar's, which shows the whole line on hover)
// is text like any other and not reported.
std::vector<CutText> find_cut_text();

std::string describe(const CutText& cut);

}  // namespace lmc::ui
