#pragma once
// One line in the Record tab for the subject screen: the toggle with its shortcut
// (F2), which monitor it covers, a windowed option for a one-monitor bench, and why it could not
// open. Changes only the operator's choice in the link; the window follows it.
#include "ui/model/record/subject_screen_link.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

// GLFW's key code for F2 (ImGui 1.86 has no named function keys; io.KeysDown uses GLFW codes).
inline constexpr int kSubjectScreenKey = 291;

class SubjectScreenControlsPanel : public Panel {
 public:
  explicit SubjectScreenControlsPanel(SubjectScreenLink& link) : Panel("##subject_screen_controls"), link_(link) {}
  void draw();
  // "toggle" as drawn (headless tests click it).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  SubjectScreenLink& link_;  // the workbench context's, which outlives every tab
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
