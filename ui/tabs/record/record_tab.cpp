// The Record tab: one subject session at the bench. Set up or resume, pre-flight per
// layout block, then trial after trial with the cue, a big red circle while recording, a strip per
// controller, and a verdict with one-key redo. Keyboard: Space starts / stops, Enter accepts a
// failed trial anyway, R redoes the last one, N adds a note, Esc aborts the running trial. All state and rules live in
// RecordState (ui/model/record/); this file lays out the panels (one class per file beside it) and maps keys and
// the buttons they report to its actions.
#include "ui/tabs/record/record_tab.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/common/paths.h"
#include "core/session/session_folder.h"
#include "ui/model/record/subject_view.h"
#include "ui/model/workbench_context.h"

namespace lmc::ui {

std::unique_ptr<Tab> make_record_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<RecordTab>(status, context);
}

RecordTab::RecordTab(StatusSink& status, WorkbenchContext& context)
    : status_(status),
      context_(context),
      model_(std::make_shared<RecordState>(&context.rig())),
      subject_(context.subject_screen()),
      setup_panel_(form_),
      trial_list_panel_(model_),
      trial_panel_(model_),
      subject_controls_(subject_) {
  refresh_sessions();
  if (auto& startup = context.record_startup()) {
    std::snprintf(form_.open_folder, sizeof form_.open_folder, "%s", startup->session.string().c_str());
    form_.backend = startup->backend == "leapc" ? 1 : 0;
    form_.fast = startup->fast;
    open_at_start_ = true;
    startup.reset();
  }
}

void RecordTab::refresh_sessions() {
  sessions_ = list_resumable_sessions(form_.sessions_folder());
}

void RecordTab::update(bool /*shown*/) {
  if (open_at_start_) {
    open_at_start_ = false;
    open();
    if (!error_.empty()) status_.set_status("Record: " + error_, true);
  }
  if (const StatusReport line = model_->poll(); !line.empty()) status_.set_status(line.text, line.is_error());
  // The subject screen follows the session every frame, whichever tab is shown.
  subject_.view = build_subject_view(subject_view_inputs(*model_), ImGui::GetTime());
  subject_.recording_s = model_->recording() && model_->live() ? model_->live()->recording_s : 0.0;
}

void RecordTab::draw() {
  if (!model_->has_session()) {
    subject_controls_.draw();
    if (const auto window = setup_panel_.window()) draw_setup();
    subject_screen_key();
    return;
  }
  if (!draw_header()) return;  // closed: nothing of the session is drawn this frame
  const float list_width = 260.0F;
  if (const auto window = trial_list_panel_.window(ImVec2(list_width, 0), true)) trial_list_panel_.draw();
  ImGui::SameLine();
  if (const auto window = trial_panel_.window(ImVec2(0, 0), true)) act(trial_panel_.draw());
  keys();
}

// The set-up form and, when a new session's subject id is already recorded, the question.
void RecordTab::draw_setup() {
  switch (setup_panel_.draw(sessions_, error_)) {
    case SetupAction::kCreate:
      create();
      break;
    case SetupAction::kOpen:
      open();
      break;
    case SetupAction::kRefreshSessions:
      refresh_sessions();
      break;
    case SetupAction::kNone:
      break;
  }
  subject_clash_question();
}

std::string RecordTab::recording_now() const {
  if (model_->recording()) return trial_name(model_->recording_trial()) + " is recording";
  if (model_->calibrating()) return "the block's calibration is recording";
  return {};
}

// One person, one subject id: a new session for an id already recorded asks what is meant.
void RecordTab::subject_clash_question() {
  constexpr const char* kTitle = "This subject id is already recorded";
  if (!subject_clash_.empty() && !ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string subject = form_.subject;
  ImGui::TextUnformatted(subject_clash_text(subject, subject_clash_).c_str());
  ImGui::Spacing();
  ImGui::TextUnformatted("One subject id is one person. What is this session?");
  const SessionListing latest = subject_clash_.front();
  // Keys too (C, A, Esc), so the question is answered without the mouse, like the Record tab.
  const bool typing = ImGui::GetIO().WantTextInput;
  if (ImGui::Button(("Continue " + latest.dir.filename().string() + "  [C]").c_str()) ||
      (!typing && ImGui::IsKeyPressed('C', false))) {
    subject_clash_.clear();
    ImGui::CloseCurrentPopup();
    std::snprintf(form_.open_folder, sizeof form_.open_folder, "%s", latest.dir.string().c_str());
    open();
  }
  ImGui::SameLine();
  if (ImGui::Button(("Add a second session of " + subject + "  [A]").c_str()) ||
      (!typing && ImGui::IsKeyPressed('A', false))) {
    subject_clash_.clear();
    ImGui::CloseCurrentPopup();
    create(true);
  }
  ImGui::SameLine();
  // The default: Enter or Esc keep the form open to change the id.
  if (ImGui::Button("Choose another id  [Esc]") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) {
    subject_clash_.clear();
    ImGui::CloseCurrentPopup();
    error_ = "subject " + subject + " is already recorded; choose another id, or Create again to continue or add";
  }
  ImGui::EndPopup();
}

void RecordTab::create(bool same_subject_confirmed) {
  if (const std::string why = check_setup_form(form_).first(); !why.empty()) {
    error_ = why;
    return;
  }
  if (!same_subject_confirmed) {
    // The demo's subjects too (S01, S02), wherever scripts/run put them: the list holds them.
    refresh_sessions();
    subject_clash_ = sessions_of_subject(sessions_, form_.subject);
    for (const auto& dir : context_.review_folders()) {
      if (!is_session_folder(dir)) continue;
      try {
        if (read_session_state(dir).subject().subject_id != form_.subject) continue;
      } catch (const std::exception&) {
        continue;
      }
      const bool listed = std::any_of(subject_clash_.begin(), subject_clash_.end(),
                                      [&](const SessionListing& s) { return s.dir == dir; });
      if (!listed) {
        const auto in_review = list_sessions(dir.parent_path());
        for (const auto& s : sessions_of_subject(in_review, form_.subject))
          if (s.dir == dir) subject_clash_.push_back(s);
      }
    }
    if (!subject_clash_.empty()) return;  // the question opens in this frame's draw
  }
  try {
    error_ = model_->create(form_.new_session_dir(), form_.spec(), form_.settings());
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  if (error_.empty()) status_.set_status("Record: session created in " + model_->dir().string());
}

void RecordTab::open() {
  error_ = model_->open(form_.open_folder, form_.settings());
  if (error_.empty()) status_.set_status("Record: session " + model_->dir().string() + " opened");
}

// Real controllers are opened once, by the workbench's live rig: the session records through
// its hub (the Devices tab keeps showing the same controllers and the same fused hand).
// False when the operator closed the session.
bool RecordTab::draw_header() {
  const auto& st = model_->state();
  ImGui::Text("Subject %s  ·  protocol %s  ·  %d of %zu trials accepted  ·  %s", st.subject().subject_id.c_str(),
              st.protocol.name.c_str(), model_->accepted_count(), st.trials.size(), model_->dir().string().c_str());
  // Close only between trials; without it the key hint below must keep its own line.
  if (!model_->busy()) {
    ImGui::SameLine(ImGui::GetWindowWidth() - 90);
    if (ImGui::SmallButton("Close")) {
      const std::string closed = model_->dir().string();
      model_->close();
      refresh_sessions();
      status_.set_status("Record: session " + closed + " closed; everything recorded is kept in its folder");
      return false;
    }
  }
  ImGui::TextDisabled(
      "Space: start / stop   Esc: abort   Enter: accept (a failed trial asks first)   R: redo   N: note");
  // The subject screen's controls beside the hint where they fit (1280 wide), else below it.
  constexpr float kSubjectControlsWidth = 520.0F;
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < kSubjectControlsWidth) ImGui::NewLine();
  subject_controls_.draw();
  return true;
}

void RecordTab::subject_screen_key() {
  if (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(kSubjectScreenKey, false)) subject_.open = !subject_.open;
}

void RecordTab::act(TrialPanelAction a) {
  if (a == TrialPanelAction::kNone) return;
  const std::optional<std::string> on_verdict = act_on_verdict(a);
  const std::string why = on_verdict ? *on_verdict : act_on_trial(a);
  if (!why.empty()) status_.set_status("Record: " + why, true);
}

// The pre-flight, the trial, the block's calibration and the note: what went wrong, "" when done.
std::string RecordTab::act_on_trial(TrialPanelAction a) {
  std::string why;
  switch (a) {
    case TrialPanelAction::kPreflight:
      why = model_->start_preflight();
      break;
    case TrialPanelAction::kOverride:
      why = model_->override_preflight(trial_panel_.override_reason());
      if (why.empty()) status_.set_status(std::string("pre-flight overridden: ") + trial_panel_.override_reason());
      break;
    case TrialPanelAction::kStart:
      why = model_->start_trial();
      if (why.empty()) status_.set_status("Record: recording " + trial_name(model_->recording_trial()));
      break;
    case TrialPanelAction::kStop:
      model_->stop_trial();
      break;
    case TrialPanelAction::kCalibrate:
      why = model_->start_calibration();
      break;
    case TrialPanelAction::kApplyCalibration:
      why = model_->apply_calibration();
      if (why.empty()) status_.set_status("Record: calibration applied; the block records with the calibrated layout");
      break;
    case TrialPanelAction::kKeepNominal:
      why = model_->keep_nominal_layout(trial_panel_.nominal_reason());
      if (why.empty()) status_.set_status(std::string("Record: nominal layout kept: ") + trial_panel_.nominal_reason());
      break;
    case TrialPanelAction::kAbort:
      why = model_->abort_trial();
      if (why.empty())
        status_.set_status("Record: trial aborted; it is kept, marked aborted, and waits for a redo (R)");
      break;
    case TrialPanelAction::kNote:
      why = model_->add_note(trial_panel_.note().text());
      if (why.empty()) {
        status_.set_status(std::string("Record: note ") +
                           (model_->busy() ? "kept; journaled when the trial ends: " : "journaled: ") +
                           trial_panel_.note().text());
        trial_panel_.note().clear();
      }
      break;
    default:
      break;
  }
  return why;
}

// What is done with the last attempt (accept, keep or not, redo) and Review this session: what
// went wrong ("" when done); nullopt for another action.
std::optional<std::string> RecordTab::act_on_verdict(TrialPanelAction a) {
  std::string why;
  switch (a) {
    case TrialPanelAction::kAccept:
      why = model_->ask_accept();
      if (why.empty() && !model_->accept_question().empty())
        status_.set_status("Record: " + model_->accept_question() + " Y keeps it, Enter or Esc does not");
      break;
    case TrialPanelAction::kKeepAnyway:
      why = model_->answer_accept(true);
      if (why.empty() && model_->last_attempt())
        status_.set_status("Record: " + trial_name(model_->last_attempt()->trial) +
                           " kept despite its verdict (journaled)");
      break;
    case TrialPanelAction::kDontKeep:
      why = model_->answer_accept(false);
      if (why.empty() && model_->last_attempt())
        status_.set_status("Record: " + trial_name(model_->last_attempt()->trial) + " not kept; R records it again");
      break;
    case TrialPanelAction::kRedo:
      why = model_->redo();
      if (why.empty())
        status_.set_status("Record: " + trial_name(model_->current_trial()) +
                           " is recorded again next; the earlier attempt is kept under superseded/");
      break;
    case TrialPanelAction::kReviewSession:
      context_.review_requests().push_back(model_->dir());
      context_.tab_request() = "review";
      break;
    default:
      return std::nullopt;
  }
  return why;
}

std::string RecordTab::trial_name(int i) const {
  const auto& trials = model_->state().trials;
  return i >= 0 && i < static_cast<int>(trials.size()) ? trials[static_cast<size_t>(i)].plan.name
                                                       : std::string("the trial");
}

void RecordTab::keys() {
  // Typing a reason or a note must not start a trial.
  if (ImGui::GetIO().WantTextInput || trial_panel_.note().awaiting_keyboard(ImGui::GetTime(), ImGui::GetFrameCount()))
    return;
  // A question (quit while recording, keep a failed trial) has the keys: Esc there is not an abort.
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
  // N first: a Space or an R typed into the note in the same frame must not act.
  if (ImGui::IsKeyPressed('N', false)) {
    trial_panel_.note().open(true);
    return;
  }
  subject_screen_key();
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) {
    if (model_->recording() || model_->calibrating())
      act(TrialPanelAction::kStop);
    else if (model_->needs_preflight())
      act(TrialPanelAction::kPreflight);
    else if (model_->needs_calibration() && !model_->pending_calibration())
      act(TrialPanelAction::kCalibrate);
    else if (!model_->pending_calibration())
      act(TrialPanelAction::kStart);
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) && model_->recording())
    act(TrialPanelAction::kAbort);
  if (model_->busy()) return;
  if (!model_->accept_question().empty()) {
    // Keeping a failed attempt is a decision: only Y keeps it; Enter (the default) and Esc do not.
    if (ImGui::IsKeyPressed('Y', false))
      act(TrialPanelAction::kKeepAnyway);
    else if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
             ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
      act(TrialPanelAction::kDontKeep);
    else if (ImGui::IsKeyPressed('R', false))
      act(TrialPanelAction::kRedo);
    return;
  }
  if (const auto& c = model_->pending_calibration()) {
    // A calibration waiting for the operator: Enter applies it, R records it again.
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) && c->ok())
      act(TrialPanelAction::kApplyCalibration);
    if (ImGui::IsKeyPressed('R', false)) act(TrialPanelAction::kCalibrate);
    return;
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) && model_->last_attempt() &&
      model_->last_attempt()->verdict() == "fail")
    act(TrialPanelAction::kAccept);
  // GLFW key codes: letters are their ASCII codes (ImGui 1.86 has no ImGuiKey_R).
  if (ImGui::IsKeyPressed('R', false)) act(TrialPanelAction::kRedo);
}

}  // namespace lmc::ui
