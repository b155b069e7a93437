#pragma once
// The Record tab's set-up form: a new subject session (subject, hand, operator,
// protocol, Vicon, folder) or an existing one to resume, and how to record it (backend, simulated
// time). Draws the form's fields (ui/model/record/record_setup_form.h) with each field's problem
// under it, and reports what was pressed; the tab turns it into model actions.
#include <string>
#include <vector>

#include "ui/model/record/record_setup_form.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

enum class SetupAction { kNone, kCreate, kOpen, kRefreshSessions };

// `sessions`: the folders under the sessions directory; a click on one fills the folder to open.
// `anchors` (tests) gets "create" and "open".
SetupAction draw_record_setup_panel(RecordSetupForm& form, const SetupFormProblems& problems,
                                    const std::vector<SessionListing>& sessions, const std::string& error,
                                    WidgetAnchors* anchors = nullptr);

}  // namespace lmc::ui
