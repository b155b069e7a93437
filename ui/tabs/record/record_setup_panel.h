#pragma once
// The Record tab's set-up form (issue #11): a new subject session (subject, hand, operator,
// protocol, Vicon, folder) or an existing one to resume, and how to record it (backend, simulated
// time). Only draws and reports what was pressed; the tab turns it into model actions.
#include <string>

#include "core/session/session_folder.h"
#include "ui/model/record/record_session_model.h"

namespace lmc::ui {

struct RecordSetupForm {
  char subject[65] = "S01";
  int handedness = 0;  // 0 right, 1 left
  float hand_length_mm = 0, hand_breadth_mm = 0;
  char operator_name[64] = "";
  char notes[256] = "";
  int protocol = 0;  // index into record_protocol_names()
  char vicon[128] = "";
  char folder[512] = "";  // empty: sessions/<subject>-<time>
  char open_folder[512] = "";
  int backend = 0;  // 0 sim, 1 leapc
  bool fast = false;

  session::NewSessionSpec spec() const;
  RecordSettings settings() const;
};

enum class SetupAction { kNone, kCreate, kOpen };

SetupAction draw_record_setup_panel(RecordSetupForm& form, const std::string& error);

}  // namespace lmc::ui
