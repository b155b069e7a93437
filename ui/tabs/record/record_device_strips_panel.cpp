#include "ui/tabs/record/record_device_strips_panel.h"

#include <imgui.h>

#include "ui/model/devices/live_hands.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
// Named, not anonymous: main compiles libraries in unity batches, where two files' kRed would meet.
namespace device_strips {

const ImVec4& kRed = palette::kFail;
const ImVec4& kGreen = palette::kOk;
const ImVec4& kAmber = palette::kWarning;

// A controller whose latest frame is older than this has stalled (a LeapC controller sends
// every 8–16 ms; the simulator's slowest rate is 11 Hz, 90 ms).
constexpr double kStaleFrameMs = 250;

void vicon_line(const devices::TrialSnapshot& live) {
  if (live.vicon_listening) {
    ImGui::Text("Vicon (listening on %s): CaptureStart", live.vicon_listen_address.c_str());
    ImGui::SameLine();
    ImGui::TextColored(live.vicon_start_received ? kGreen : kAmber, live.vicon_start_received ? "received" : "awaited");
    ImGui::SameLine();
    ImGui::TextUnformatted(" · CaptureStop");
    ImGui::SameLine();
    ImGui::TextColored(live.vicon_stop_received ? kGreen : kAmber, live.vicon_stop_received ? "received" : "awaited");
  } else if (live.vicon_sending) {
    ImGui::Text("Vicon: %d trigger packet(s) sent", live.vicon_packets_sent);
  } else {
    ImGui::TextDisabled("Vicon: not used by this session");
  }
}

}  // namespace device_strips

void RecordDeviceStripsPanel::draw() {
  if (!model_->live()) return;
  const devices::TrialSnapshot& live = *model_->live();
  ImGui::Text("Frames written %lld", static_cast<long long>(live.recorder.frames_written));
  ImGui::SameLine();
  ImGui::TextDisabled("  ·  ");
  ImGui::SameLine();
  device_strips::vicon_line(live);
  if (!ImGui::BeginTable("strips", 6, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingFixedFit)) return;
  ImGui::TableSetupColumn("Slot");
  ImGui::TableSetupColumn("Controller");
  ImGui::TableSetupColumn("Rate");
  // Fixed widths for the cells whose text changes while recording: fitted to the first frame's
  // "hand", the column cut a later "no hand" to "no ha".
  ImGui::TableSetupColumn("Hand", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("no hand").x);
  ImGui::TableSetupColumn("Frame age", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("Frame age").x);
  ImGui::TableSetupColumn("Dropped");
  ImGui::TableHeadersRow();
  for (const auto& d : live.hub.devices) {
    if (d.slot.empty()) continue;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const auto rgb = device_colour(d.slot_index);
    ImGui::TextColored(ImVec4(rgb[0], rgb[1], rgb[2], 1.0F), "%s", d.slot.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(d.serial.c_str());
    ImGui::TableNextColumn();
    if (!d.connected)
      ImGui::TextColored(device_strips::kRed, "LOST");
    else
      ImGui::Text("%.0f Hz", d.rate_hz);
    ImGui::TableNextColumn();
    if (d.hand_present)
      ImGui::TextColored(device_strips::kGreen, "hand");
    else
      ImGui::TextColored(device_strips::kRed, "no hand");
    ImGui::TableNextColumn();
    if (d.latest_frame_age_ms < 0)
      ImGui::TextDisabled("-");
    else if (d.latest_frame_age_ms > device_strips::kStaleFrameMs)
      ImGui::TextColored(device_strips::kRed, "%.0f ms", d.latest_frame_age_ms);
    else
      ImGui::Text("%.0f ms", d.latest_frame_age_ms);
    ImGui::TableNextColumn();
    const long long dropped = static_cast<long long>(d.frames_dropped + d.frames_dropped_recorder);
    if (dropped > 0)
      ImGui::TextColored(device_strips::kAmber, "%lld", dropped);
    else
      ImGui::TextDisabled("0");
  }
  ImGui::EndTable();
}

}  // namespace lmc::ui
