#include "ui/tabs/record/record_verdict_panel.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "ui/model/devices/live_hands.h"
#include "ui/tabs/record/record_colours.h"
#include "ui/widgets/colour_legend.h"
#include "ui/widgets/timeline_plot.h"

namespace lmc::ui {
// Named, not anonymous: main compiles libraries in unity batches, where two files' kRed would meet.
namespace verdict_panel {

std::string percent(double f) {
  if (!std::isfinite(f)) return "-";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f %%", 100.0 * f);
  return buf;
}

void key_figures(const session::QualityReport& q) {
  ImGui::Text("Recorded %.1f of %.1f s  ·  hand present %s", q.duration_s, q.planned_s,
              percent(q.hand_fraction).c_str());
  if (!q.finger_seen_fraction.empty()) {
    std::string line = "Seen by at least 1 controller:";
    for (size_t k = 0; k < q.finger_seen_fraction.size() && k < kNumDigits; ++k)
      line += "  " + std::string(digit_name(static_cast<int>(k))) + " " + percent(q.finger_seen_fraction[k]);
    ImGui::TextUnformatted(line.c_str());
  }
  std::string devices;
  for (const auto& d : q.devices) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s %.0f Hz, hand %s", devices.empty() ? "" : "  ·  ", d.slot.c_str(),
                  d.median_rate_hz, percent(d.hand_fraction).c_str());
    devices += buf;
  }
  if (!devices.empty()) ImGui::TextUnformatted(devices.c_str());
  if (q.rom && std::isfinite(q.rom->reached_deg))
    ImGui::Text("%s moved through %.0f degrees; the protocol expects %.0f", q.rom->joint.c_str(), q.rom->reached_deg,
                q.rom->expected_deg);
}

// Each controller's hand presence (0-1) and fingers seen (0-5) over the trial, one colour per
// slot as in the live view; the worst finger's seen-by count in white.
void timeline(const session::QualityTimeline& t) {
  if (t.slices() < 2) return;
  std::vector<TimelineSeries> hands;
  std::vector<TimelineSeries> fingers;
  std::vector<LegendEntry> legend;  // which colour is which controller: the plots are read without hovering
  for (size_t d = 0; d < t.device_ids.size(); ++d) {
    const std::string slot = "LMC" + std::to_string(t.device_ids[d]);
    const auto rgb = device_colour(t.device_ids[d] - 1);
    hands.push_back({slot + " hand", rgb, t.hand_present[d]});
    fingers.push_back({slot + " fingers seen", rgb, t.fingers_seen[d]});
    legend.push_back({Rgba{rgb[0], rgb[1], rgb[2], 1.0F}, slot});
  }
  fingers.push_back({"least-seen finger: controllers", {1, 1, 1}, t.worst_finger_seen_by, 2.5F});
  TimelinePlotOptions o;
  o.slice_s = t.slice_s;
  o.height_px = 60;
  legend.push_back({Rgba{1, 1, 1, 1}, "least-seen finger"});
  draw_categorical_legend(legend);
  ImGui::TextDisabled("Hand present per controller (0-1)");
  draw_timeline_plot("hand_present", hands, o);
  o.y_max = kNumDigits;
  o.height_px = 80;
  ImGui::TextDisabled("Fingers each controller sees (0-5); white: how many controllers see the least-seen finger");
  draw_timeline_plot("seen_by", fingers, o);
}

}  // namespace verdict_panel

VerdictAction draw_record_verdict_panel(const RecordSessionModel& model, NoteInput& note) {
  VerdictAction action = VerdictAction::kNone;
  const auto& a = model.last_attempt();
  if (!a) return action;
  const auto& trial = model.state().trials.at(static_cast<size_t>(a->trial));
  ImGui::Separator();
  ImGui::Text("%s, attempt %d: %s", trial.plan.name.c_str(), a->attempt, a->outcome.c_str());
  ImGui::SameLine();
  ImGui::SetWindowFontScale(1.3F);
  ImGui::TextColored(verdict_colour(a->verdict()), "  %s", a->verdict().c_str());
  ImGui::SetWindowFontScale(1.0F);
  if (a->quality) {
    for (const auto& why : a->quality->reasons) ImGui::BulletText("%s", why.c_str());
    if (a->quality->reasons.empty()) ImGui::BulletText("every check passed");
    verdict_panel::key_figures(*a->quality);
  }
  const bool accepted = trial.status == session::TrialStatus::kAccepted;
  if (!model.busy()) {
    if (!accepted && ImGui::Button("Accept anyway  [Enter]")) action = VerdictAction::kAccept;
    if (!accepted) ImGui::SameLine();
    if (ImGui::Button("Redo this trial  [R]")) action = VerdictAction::kRedo;
    ImGui::SameLine();
  }
  if (ImGui::Button("Note  [N]")) open_note(note);
  if (accepted && !model.busy()) {
    ImGui::SameLine();
    ImGui::TextDisabled("accepted; R records it again and keeps this attempt under superseded/");
  }
  // Only this attempt's notes: an earlier attempt's "glove slipped" says nothing about this one.
  for (const auto& attempt : trial.attempts)
    if (attempt.number == a->attempt)
      for (const auto& n : attempt.notes) ImGui::TextDisabled("note: %s", n.c_str());
  if (a->quality) verdict_panel::timeline(a->quality->timeline);
  return action;
}

void open_note(NoteInput& note, bool by_key) {
  if (note.open) {
    note.focus = !note.took_keyboard;
    return;
  }
  note = NoteInput{};
  note.open = true;
  note.focus = true;
  note.opened_frame = ImGui::GetFrameCount();
  note.opened_time = ImGui::GetTime();
  if (by_key) {
    // A fast typist's first letters can arrive in the same frame as the N: keep what follows it.
    const ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    bool after_n = false;
    for (ImWchar c : queue) {
      if (after_n)
        note.held.push_back(c);
      else
        after_n = c == 'n' || c == 'N';
    }
  }
}

bool draw_note_line(const RecordSessionModel& model, NoteInput& note) {
  bool submitted = false;
  if (note.open) {
    if (note.focus) {
      ImGui::SetKeyboardFocusHere();
      note.focus = false;
    }
    // Characters typed after N but before the field has the keyboard (the N's own 'n' arrives in
    // the frame that opened the line and is left out); an Enter or Esc among them is kept too.
    const bool early = !note.took_keyboard && ImGui::GetFrameCount() > note.opened_frame;
    ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    if (early) {
      note.held.insert(note.held.end(), queue.begin(), queue.end());
      queue.resize(0);
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) note.submit_when_typed = true;
    } else if (note.took_keyboard && !note.held.empty()) {
      ImVector<ImWchar> typed;
      for (ImWchar c : note.held) typed.push_back(c);
      for (ImWchar c : queue) typed.push_back(c);
      queue.swap(typed);
      note.held.clear();
    }
    ImGui::PushItemWidth(420);
    const int target = model.note_trial();
    const std::string hint =
        "note on " +
        (target >= 0 ? model.state().trials.at(static_cast<size_t>(target)).plan.name : std::string("the trial")) +
        ": Enter keeps it, Esc drops it";
    const bool enter = ImGui::InputTextWithHint("##note", hint.c_str(), note.text, sizeof note.text,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    const bool active = ImGui::IsItemActive();
    const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    if (active) note.took_keyboard = true;
    if (enter) {
      // An Enter in the very frame the field took the keyboard, with held letters not yet typed
      // into it, waits for them.
      if (note.held.empty())
        submitted = true;
      else
        note.submit_when_typed = true;
    } else if (note.submit_when_typed && note.took_keyboard && note.held.empty()) {
      submitted = true;
      note.submit_when_typed = false;
    }
    if (escape && (active || ImGui::IsItemDeactivated() || early)) {
      note = NoteInput{};
    }
    ImGui::PopItemWidth();
  }
  return submitted;
}

}  // namespace lmc::ui
