// The Record tab (issue #11): one subject session at the bench. Set up or resume, pre-flight per
// layout block, then trial after trial with the cue, a big red circle while recording, a strip per
// controller, and a verdict with one-key redo. Keyboard: Space starts / stops, Enter accepts a
// failed trial anyway, R redoes the last one, N adds a note, Esc aborts the running trial. All state and rules live in RecordSessionModel
// (ui/model/record/); this file lays out the panels and maps keys and buttons to its actions.
#include "ui/tabs/record/record_tab.h"

#include <imgui.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core/session/session_folder.h"
#include "ui/model/record/record_session_model.h"
#include "ui/model/workbench_context.h"
#include "ui/tabs/record/record_setup_panel.h"
#include "ui/tabs/record/record_trial_list_panel.h"
#include "ui/tabs/record/record_trial_panel.h"

namespace lmc::ui {
namespace {

class RecordTab final : public Tab {
 public:
  RecordTab(StatusSink& status, WorkbenchContext& context) : status_(status), model_(&context.rig()) {
    if (auto& startup = context.record_startup()) {
      std::snprintf(form_.open_folder, sizeof form_.open_folder, "%s", startup->session.string().c_str());
      form_.backend = startup->backend == "leapc" ? 1 : 0;
      form_.fast = startup->fast;
      open_at_start_ = true;
      startup.reset();
    }
  }

  void update() override {
    if (open_at_start_) {
      open_at_start_ = false;
      open();
      if (!error_.empty()) status_.set_status("Record: " + error_, true);
    }
    if (const std::string line = model_.poll(); !line.empty()) {
      const bool bad = line.find(": fail") != std::string::npos || line.find("failed") != std::string::npos;
      status_.set_status(line, bad);
    }
    if (capture_) drive_capture();
  }

  void draw() override {
    if (!model_.has_session()) {
      ImGui::BeginChild("setup", ImVec2(0, 0), false);
      switch (draw_record_setup_panel(form_, error_)) {
        case SetupAction::kCreate: create(); break;
        case SetupAction::kOpen: open(); break;
        case SetupAction::kNone: break;
      }
      ImGui::EndChild();
      return;
    }
    draw_header();
    const float list_width = 260.0F;
    ImGui::BeginChild("trials", ImVec2(list_width, 0), true);
    const int clicked = draw_record_trial_list(model_.state(), model_.current_trial(), model_.recording_trial());
    if (clicked >= 0 && !model_.busy()) model_.select(clicked);
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginChild("trial", ImVec2(0, 0), true);
    act(draw_record_trial_panel(model_, panel_));
    ImGui::EndChild();
    keys();
  }

  int prepare_for_capture() override {
    capture_ = true;
    return 4;
  }
  bool busy_for_capture() const override {
    const bool mid_second_trial = model_.last_attempt() && model_.recording() && model_.live() &&
                                  model_.live()->recording_s > 1.5 && model_.live_fused();
    return capture_ && !mid_second_trial;
  }

 private:
  void create() {
    try {
      const session::NewSessionSpec spec = form_.spec();
      const std::filesystem::path dir =
          form_.folder[0] != '\0' ? std::filesystem::path(form_.folder) : session::default_session_dir(form_.subject);
      error_ = model_.create(dir, spec, settings());
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    if (error_.empty()) status_.set_status("Record: session created in " + model_.dir().string());
  }

  void open() {
    error_ = model_.open(form_.open_folder, settings());
    if (error_.empty()) status_.set_status("Record: session " + model_.dir().string() + " opened");
  }

  // Real controllers are opened once, by the workbench's live rig: the session records through
  // its hub (the Devices tab keeps showing the same controllers and the same fused hand).
  RecordSettings settings() const {
    RecordSettings s = form_.settings();
    s.share_rig_hub = s.backend == "leapc";
    return s;
  }

  void draw_header() {
    const auto& st = model_.state();
    ImGui::Text("Subject %s  ·  protocol %s  ·  %d of %zu trials accepted  ·  %s", st.subject().subject_id.c_str(),
                st.protocol.name.c_str(), model_.accepted_count(), st.trials.size(), model_.dir().string().c_str());
    // Close only between trials; without it the key hint below must keep its own line.
    if (!model_.busy()) {
      ImGui::SameLine(ImGui::GetWindowWidth() - 90);
      if (ImGui::SmallButton("Close")) model_.close();
    }
    ImGui::TextDisabled("Space: start / stop   Esc: abort   Enter: accept a failed trial anyway   R: redo the last trial   N: note");
  }

  void act(TrialPanelAction a) {
    std::string why;
    switch (a) {
      case TrialPanelAction::kNone: return;
      case TrialPanelAction::kPreflight: why = model_.start_preflight(); break;
      case TrialPanelAction::kOverride:
        why = model_.override_preflight(panel_.override_reason);
        if (why.empty()) status_.set_status(std::string("pre-flight overridden: ") + panel_.override_reason);
        break;
      case TrialPanelAction::kStart: why = model_.start_trial(); break;
      case TrialPanelAction::kStop: model_.stop_trial(); break;
      case TrialPanelAction::kAbort:
        why = model_.abort_trial();
        if (why.empty()) status_.set_status("Record: trial aborted; it is kept, marked aborted, and waits for a redo (R)");
        break;
      case TrialPanelAction::kNote:
        why = model_.add_note(panel_.note.text);
        if (why.empty()) {
          status_.set_status(std::string("Record: note ") + (model_.busy() ? "kept; journaled when the trial ends: " : "journaled: ") +
                             panel_.note.text);
          panel_.note = {};
        }
        break;
      case TrialPanelAction::kAccept: why = model_.accept_last(); break;
      case TrialPanelAction::kRedo: why = model_.redo(); break;
    }
    if (!why.empty()) status_.set_status("Record: " + why, true);
  }

  void keys() {
    // Typing a reason or a note must not start a trial.
    if (ImGui::GetIO().WantTextInput) return;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) {
      if (model_.recording()) act(TrialPanelAction::kStop);
      else if (model_.needs_preflight()) act(TrialPanelAction::kPreflight);
      else act(TrialPanelAction::kStart);
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) && model_.recording()) act(TrialPanelAction::kAbort);
    if (ImGui::IsKeyPressed('N', false)) open_note(panel_.note);
    if (model_.busy()) return;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) && model_.last_attempt() &&
        model_.last_attempt()->verdict() == "fail")
      act(TrialPanelAction::kAccept);
    // GLFW key codes: letters are their ASCII codes (ImGui 1.86 has no ImGuiKey_R).
    if (ImGui::IsKeyPressed('R', false)) act(TrialPanelAction::kRedo);
  }

  // --capture: a quick session on the simulated rig in real time (no countdown). The first trial
  // is recorded to its verdict, then the picture is taken 1.5 s into the second, so it shows the
  // trial list with a verdict, the cue, the red circle, the controller strips and the fused hand.
  void drive_capture() {
    if (!model_.has_session()) {
      const auto dir = std::filesystem::temp_directory_path() / ("lmc-record-capture-" + std::to_string(::getpid()));
      std::filesystem::remove_all(dir);
      form_.protocol = 1;
      RecordSettings settings = form_.settings();
      settings.fast = false;
      settings.countdown_s = 0;
      error_ = model_.create(dir, form_.spec(), settings);
      return;
    }
    if (model_.busy()) return;
    if (model_.needs_preflight()) {
      if (!model_.last_preflight()) model_.start_preflight();
      else model_.override_preflight("screenshot");
      return;
    }
    if (!model_.finished()) model_.start_trial();
  }

  StatusSink& status_;
  RecordSessionModel model_;
  RecordSetupForm form_;
  TrialPanelInput panel_;
  std::string error_;
  bool capture_ = false;
  bool open_at_start_ = false;
};

}  // namespace

std::unique_ptr<Tab> make_record_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<RecordTab>(status, context);
}

}  // namespace lmc::ui
