#include "ui/tabs/record/record_trial_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/model/devices/fusion_readout.h"
#include "ui/model/record/motion_pictogram.h"
#include "ui/model/record/subject_view.h"
#include "ui/tabs/record/record_colours.h"
#include "ui/widgets/hand_pictogram.h"
#include "ui/widgets/live_hands_view.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

const ImVec4& kRed = palette::kFail;
const ImVec4& kGreen = palette::kOk;

void big_text(const std::string& text, float scale) {
  ImGui::SetWindowFontScale(scale);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::SetWindowFontScale(1.0F);
}

bool big_button(const char* label, ImVec4 colour) {
  ImGui::PushStyleColor(ImGuiCol_Button, colour);
  ImGui::SetWindowFontScale(1.4F);
  const bool pressed = ImGui::Button(label, ImVec2(260, 52));
  ImGui::SetWindowFontScale(1.0F);
  ImGui::PopStyleColor();
  return pressed;
}

// The study's recording cue: a big red circle the subject cannot miss.
void recording_circle(bool counting_down) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float r = 34.0F;
  const ImU32 fill = counting_down ? palette::kCountdownCircle : palette::kRecordingCircle;
  dl->AddCircleFilled(ImVec2(p.x + r, p.y + r), r, fill, 48);
  ImGui::Dummy(ImVec2(2 * r + 8, 2 * r));
}

// A green or red line per check, with its reason.
void preflight_checklist(const devices::PreflightReport& report) {
  ImGui::Text("Pre-flight for layout '%s':", report.layout_name.c_str());
  for (const auto& item : report.items) {
    ImGui::TextColored(item.ok ? kGreen : kRed, item.ok ? " ok  " : " FAIL");
    ImGui::SameLine();
    ImGui::TextWrapped("%s: %s", item.check.c_str(), item.detail.c_str());
  }
  ImGui::Spacing();
}

}  // namespace

RecordTrialPanel::RecordTrialPanel(std::shared_ptr<const RecordState> model)
    : Panel("trial"), model_(model), note_(model), verdict_(model, note_), calibration_(model), strips_(model) {}

TrialPanelAction RecordTrialPanel::preflight_section() {
  const RecordState& model = *model_;
  TrialPanelAction action = TrialPanelAction::kNone;
  ImGui::TextWrapped("%s", model.block_instructions().c_str());
  ImGui::Spacing();
  if (const auto& report = model.last_preflight()) preflight_checklist(*report);
  // One action per key: Space runs the pre-flight here; Start appears once the block is cleared.
  if (big_button("Run pre-flight  [Space]", palette::kButtonAction)) action = TrialPanelAction::kPreflight;
  anchors_.remember("preflight");
  ImGui::TextDisabled(
      "Start [Space] comes when every pre-flight line is green, or after an override with a typed "
      "reason (journaled).");
  if (model.last_preflight() && !model.last_preflight()->ok()) {
    ImGui::Spacing();
    ImGui::PushItemWidth(360);
    ImGui::InputTextWithHint("##reason", "why go ahead anyway (journaled)", override_reason_, sizeof override_reason_);
    ImGui::PopItemWidth();
    ImGui::SameLine();
    if (ImGui::Button("Override")) action = TrialPanelAction::kOverride;
    anchors_.remember("override");
  }
  return action;
}

// The verdict (record_verdict_panel.h) and the note line, as this panel's actions.
void RecordTrialPanel::verdict_section(TrialPanelAction& action) {
  switch (verdict_.draw()) {
    case VerdictAction::kAccept:
      action = TrialPanelAction::kAccept;
      break;
    case VerdictAction::kKeepAnyway:
      action = TrialPanelAction::kKeepAnyway;
      break;
    case VerdictAction::kDontKeep:
      action = TrialPanelAction::kDontKeep;
      break;
    case VerdictAction::kRedo:
      action = TrialPanelAction::kRedo;
      break;
    case VerdictAction::kNone:
      break;
  }
  if (note_.draw()) action = TrialPanelAction::kNote;
}

// The block's controllers where the layout puts them and, while recording, each one's hand.
void RecordTrialPanel::live_view() {
  const RecordState& model = *model_;
  const Layout* layout = model.current_layout();
  if (!layout) return;
  ImGui::Spacing();
  const auto& fused = model.live_fused();
  if (fused) {
    ImGui::TextDisabled(
        "Fused hand: fingers by how many controllers see them now (red none, orange 1, yellow 2, green 3+)");
    ImGui::TextDisabled("%s", fusion_latency_line(model.fusion_stats()).c_str());
    int unseen = 0;
    for (int n : fused->seen_by) unseen += n == 0 ? 1 : 0;
    if (unseen > 0 && fused->has_hand) {
      ImGui::SameLine();
      ImGui::TextColored(kRed, "  %d finger(s) seen by no controller", unseen);
    }
  }
  draw_live_hands_view("record_live", camera_, *layout, model.live_hands(),
                       "Layout '" + layout->name +
                           "' in the world frame (mm): each controller's hand in its colour, "
                           "the fused hand thick.",
                       fused ? &*fused : nullptr);
}

TrialPanelAction RecordTrialPanel::draw() {
  anchors_.clear();  // only what this frame drew
  const RecordState& model = *model_;
  TrialPanelAction action = TrialPanelAction::kNone;
  // The plain notice of a resumed session, until the first attempt of this run begins.
  ImGui::PushStyleColor(ImGuiCol_Text, palette::kAttention);
  for (const auto& line : model.resume_notice()) ImGui::TextWrapped("%s", line.c_str());
  ImGui::PopStyleColor();

  const int i = model.recording() ? model.recording_trial() : model.current_trial();
  if (i < 0) {
    big_text("Every trial is accepted. The session is complete.", 1.5F);
    ImGui::TextWrapped("Folder: %s.", model.dir().string().c_str());
    if (ImGui::Button("Review this session")) action = TrialPanelAction::kReviewSession;
    ImGui::SameLine();
    ImGui::TextDisabled("opens it in the Review tab: every trial against Vicon, agreement, figures");
    verdict_section(action);
    return action;
  }
  draw_cues(i);
  if (model.recording()) {
    action = recording_section(i);
    strips_.draw();
  } else if (model.needs_preflight()) {
    const TrialPanelAction a = preflight_section();
    verdict_section(action);
    if (a != TrialPanelAction::kNone) action = a;
  } else if (model.needs_calibration() || model.calibrating() || model.pending_calibration()) {
    action = calibration_.draw();
  } else {
    action = start_section(i);
    verdict_section(action);
  }
  live_view();
  return action;
}

// Which trial, its name, the operator's and the subject's cues, and the motion's pictogram (what
// the subject screen shows) on the right.
void RecordTrialPanel::draw_cues(int i) {
  const RecordState& model = *model_;
  const auto& state = model.state();
  const auto& trial = state.trials.at(static_cast<size_t>(i));
  const auto& type = model.trial_type(i);
  const auto& pose = state.protocol.poses.at(static_cast<size_t>(trial.plan.pose));
  ImGui::TextDisabled("Trial %d of %zu  ·  layout %s  ·  palm %s  ·  %.0f s", i + 1, state.trials.size(),
                      trial.plan.layout_key.c_str(), pose.key.c_str(), type.duration_s);
  const ImVec2 cue_top = ImGui::GetCursorScreenPos();
  const float pictogram_w = 230.0F, pictogram_h = 150.0F;
  const float cue_width = ImGui::GetContentRegionAvail().x - pictogram_w - 12.0F;
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + cue_width);
  big_text(trial.plan.name, 2.0F);
  ImGui::TextWrapped("Operator: %s", type.operator_cue.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, palette::kCue);
  big_text("Subject: " + type.subject_cue, 1.4F);
  ImGui::PopStyleColor();
  // Overridden in this run (a pre-flight that passed since says nothing more).
  if (const auto it = state.preflight_override.find(trial.plan.layout_key);
      it != state.preflight_override.end() && !(model.last_preflight() && model.last_preflight()->ok()))
    ImGui::TextColored(palette::kWarning, "Pre-flight overridden: %s (journaled)", it->second.c_str());
  ImGui::PopTextWrapPos();
  const float cue_bottom = ImGui::GetCursorScreenPos().y;
  if (const auto pictogram =
          motion_pictogram(trial.plan.sim_motion, ImGui::GetTime(), state.subject().hand_length_mm.value_or(0.0),
                           state.subject().hand_breadth_mm.value_or(0.0))) {
    ImGui::SetCursorScreenPos(ImVec2(cue_top.x + cue_width + 12.0F, cue_top.y));
    draw_hand_pictogram(*pictogram, ImVec2(pictogram_w, pictogram_h));
  }
  ImGui::SetCursorScreenPos(ImVec2(cue_top.x, std::max(cue_bottom, cue_top.y + pictogram_h + 4.0F)));
  ImGui::Spacing();
}

// While trial `i` records: the circle, where it is (waiting, counting down, recording), Stop, Abort
// and Note.
TrialPanelAction RecordTrialPanel::recording_section(int i) {
  const RecordState& model = *model_;
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto& type = model.trial_type(i);
  const auto& live = model.live();
  const bool counting = live && live->phase == devices::TrialPhase::kCountdown;
  recording_circle(counting || !live || live->phase == devices::TrialPhase::kWaitingForStreams);
  ImGui::SameLine();
  ImGui::BeginGroup();
  if (!live) {
    big_text("starting...", 1.4F);
  } else if (live->phase == devices::TrialPhase::kWaitingForStreams) {
    big_text("waiting for every controller", 1.4F);
  } else if (counting) {
    char text[64];
    // The number the subject sees at this moment (subject_view.h: one rule for both screens).
    std::snprintf(text, sizeof text, "starts in %d s", countdown_number(live->countdown_remaining_s));
    big_text(text, 1.6F);
  } else {
    char text[96];
    // Counted from the protocol's duration, which is what the subject was told.
    std::snprintf(text, sizeof text, "RECORDING  %.1f s  ·  %d s left", live->recording_s,
                  seconds_left(type.duration_s, live->recording_s));
    big_text(text, 1.6F);
    const float f = type.duration_s > 0 ? static_cast<float>(live->recording_s / type.duration_s) : 0.0F;
    ImGui::ProgressBar(std::clamp(f, 0.0F, 1.0F), ImVec2(360, 0));
  }
  ImGui::EndGroup();
  if (big_button("Stop  [Space]", palette::kButtonStop)) action = TrialPanelAction::kStop;
  ImGui::SameLine();
  if (ImGui::Button("Abort  [Esc]", ImVec2(160, 52))) action = TrialPanelAction::kAbort;
  ImGui::SameLine();
  if (ImGui::Button("Note  [N]", ImVec2(120, 52))) note_.open();
  if (note_.draw()) action = TrialPanelAction::kNote;
  return action;
}

// Between trials, with the block's pre-flight passed and no calibration waiting: Start.
TrialPanelAction RecordTrialPanel::start_section(int i) {
  const RecordState& model = *model_;
  TrialPanelAction action = TrialPanelAction::kNone;
  const auto& trial = model.state().trials.at(static_cast<size_t>(i));
  // The checklist that enabled Start stays in view until the block's first trial of this run.
  if (const auto& report = model.last_preflight(); report && report->ok() && !model.last_attempt())
    preflight_checklist(*report);
  if (model.preflight_running()) {
    // The block's checks run on the worker: say so where Start will appear (a Space pressed now
    // is answered in the status line).
    ImGui::TextUnformatted("Pre-flight: checking the controllers, Vicon, disk and folder...");
  } else if (!model.busy() && trial.status == TrialStatus::kAccepted) {
    // A trial picked in the list that is already kept: Start would be refused, so it is not offered.
    ImGui::TextColored(kGreen, "%s is accepted.", trial.plan.name.c_str());
    ImGui::TextDisabled("R records it again (this attempt is kept under superseded/); pick another trial in the list.");
  } else if (!model.busy()) {
    if (big_button("Start  [Space]", palette::kButtonGo)) action = TrialPanelAction::kStart;
    anchors_.remember("start");
  }
  if (trial.attempts.size() > 0 && trial.status != TrialStatus::kAccepted)
    ImGui::TextDisabled("attempt %zu of this trial", trial.attempts.size() + 1);
  return action;
}

}  // namespace lmc::ui
