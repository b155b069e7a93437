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
#include "ui/widgets/palette.h"
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

void key_figures(const QualityReport& q) {
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
void timeline(const QualityTimeline& t) {
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

VerdictAction RecordVerdictPanel::draw() {
  anchors_.clear();  // only what this frame drew
  const RecordState& model = *model_;
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
  const bool accepted = trial.status == TrialStatus::kAccepted;
  if (!model.busy() && !model.accept_question().empty()) {
    // The question Enter opened: No is the default (Enter again), keeping takes a Y or a click.
    ImGui::PushStyleColor(ImGuiCol_Text, palette::kWarning);
    ImGui::TextWrapped("%s", model.accept_question().c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("No, keep it failed  [Enter]")) action = VerdictAction::kDontKeep;
    anchors_.remember("dont_keep");
    ImGui::SameLine();
    if (ImGui::Button("Keep it anyway (journaled)  [Y]")) action = VerdictAction::kKeepAnyway;
    anchors_.remember("keep_anyway");
  } else if (!model.busy()) {
    if (!accepted) {
      if (ImGui::Button("Accept anyway  [Enter]")) action = VerdictAction::kAccept;
      anchors_.remember("accept");
      ImGui::SameLine();
    }
    if (ImGui::Button("Redo this trial  [R]")) action = VerdictAction::kRedo;
    anchors_.remember("redo");
    ImGui::SameLine();
  }
  if (ImGui::Button("Note  [N]")) note_.open();
  anchors_.remember("note");
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

}  // namespace lmc::ui
