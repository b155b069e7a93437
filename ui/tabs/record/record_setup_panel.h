#pragma once
// The Record tab's set-up form: a new subject session (subject, hand, operator,
// protocol, Vicon, folder) or an existing one to resume, and how to record it (backend, simulated
// time). Draws the form's fields (ui/model/record/record_setup_form.h) with each field's problem
// under it, and reports what was pressed; the tab turns it into model actions.
#include <string>
#include <vector>

#include "ui/model/record/record_setup_form.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

enum class SetupAction { kNone, kCreate, kOpen, kRefreshSessions };

class RecordSetupPanel : public Panel {
 public:
  // `form`: the tab's, edited in place as the operator types.
  explicit RecordSetupPanel(RecordSetupForm& form) : Panel("setup"), form_(form) {}
  // `sessions`: the folders under the sessions directory; a click on one fills the folder to open.
  // `error`: why the last create or open failed ("" = none).
  SetupAction draw(const std::vector<SessionListing>& sessions, const std::string& error);
  // "create" and "open" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  SetupAction draw_new_session();
  SetupAction draw_resume(const std::vector<SessionListing>& sessions);

  RecordSetupForm& form_;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
