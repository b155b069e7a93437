// The Devices tab: every connected controller (or the simulated rig) with serial,
// slot (assign by dropdown), backend, model, tracking mode, status, rate, hand present and latest
// frame age; a live 3-D view of every device's hand realigned into the world frame, one colour per
// device, so a misplaced controller shows at a glance; start/stop of a test recording through the
// one trial engine; the Calibrate step (devices_calibrate_panel.h) above the device log. It drives the
// workbench's live rig (shared with the Record tab) with the layout open in the Layout tab. All
// logic lives in ui/model/devices/devices_view_model.h; this file only draws (ImGui draw list
// through the shared orbit camera and hand bones of ui/scene).
#include "ui/tabs/devices/devices_tab.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/common/paths.h"
#include "core/io/layout_json.h"
#include "devices/sim/sim_config.h"
#include "devices/source_factory.h"
#include "ui/model/devices/devices_view_model.h"
#include "ui/model/devices/fusion_readout.h"
#include "ui/scene/orbit_camera.h"
#include "ui/scene/scene_items.h"
#include "ui/tabs/capture_scratch.h"
#include "ui/tabs/devices/devices_calibrate_panel.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/live_hands_view.h"

namespace lmc::ui {
namespace {

class DevicesTab final : public Tab {
 public:
  DevicesTab(StatusSink& status, WorkbenchContext& context)
      : status_(status), vm_(context.rig()), calibrate_(status, context) {
    const std::string tmp = (sessions_dir() / "test-recordings").string();
    std::snprintf(folder_, sizeof folder_, "%s", tmp.c_str());
    std::snprintf(trial_, sizeof trial_, "%s", "test_trial_1");
  }

  void update(bool /*shown*/) override {
    vm_.refresh();
    // Layout restarts and trial outcomes reach the status bar whichever tab started them.
    const auto& log = vm_.messages();
    const std::uint64_t fresh = std::min<std::uint64_t>(vm_.rig().messages_total() - seen_messages_, log.size());
    for (size_t i = log.size() - static_cast<size_t>(fresh); i < log.size(); ++i) {
      if (log[i].rfind("layout changed", 0) == 0) status_.set_status("Devices: " + log[i]);
    }
    seen_messages_ = vm_.rig().messages_total();
    calibrate_.update();
    if (const std::string summary = vm_.take_recording_summary(); !summary.empty()) {
      // "trial NAME completed|interrupted|aborted|failed…": only the last two are errors.
      const bool ok =
          summary.find(" completed") != std::string::npos || summary.find(" interrupted") != std::string::npos;
      status_.set_status(summary, !ok);
    }
    if (!vm_.running()) return;
    // With the SDK present, LeapC is tried first; without controllers the simulated rig takes over.
    if (fallback_pending_ && vm_.running_seconds() > 3.0) {
      fallback_pending_ = false;
      if (vm_.rows().empty()) {
        status_.set_status("no controller found: running the simulated rig");
        start("sim");
      }
    }
  }

  void draw() override {
    if (!auto_started_) {
      auto_started_ = true;
      if (devices::leapc_available()) {
        fallback_pending_ = true;
        start("leapc");
      } else {
        start("sim");
      }
    }
    draw_toolbar();
    ImGui::Separator();
    draw_table();
    ImGui::Separator();
    draw_recording_row();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side_width = std::max(380.0F, avail.x * 0.36F);
    ImGui::BeginChild("live_view", ImVec2(avail.x - side_width - 8.0F, avail.y), true,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    draw_live_view();
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginGroup();
    // The Calibrate step above the log: its result table needs most of the height while shown.
    const CalibrationStage stage = calibrate_.step().stage();
    const bool result = stage == CalibrationStage::kResult || stage == CalibrationStage::kApplied;
    const float line = ImGui::GetFrameHeightWithSpacing();
    const float calibrate_height = result ? std::max(avail.y * 0.72F, avail.y - 6.0F * line) : 5.0F * line;
    ImGui::BeginChild("calibrate", ImVec2(side_width, calibrate_height), true);
    calibrate_.draw();
    ImGui::EndChild();
    ImGui::BeginChild("device_log", ImVec2(side_width, 0), true);
    ImGui::TextDisabled("Device messages");
    for (const auto& m : vm_.messages()) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0F);
    ImGui::EndChild();
    ImGui::EndGroup();
    handle_shortcuts();
  }

  int prepare_for_capture() override {
    if (!vm_.running() || vm_.backend() != "sim") {
      auto_started_ = true;
      start("sim");
    }
    return 30;
  }

  bool busy_for_capture() const override { return (vm_.running() && !vm_.all_streaming()) || calibrate_.step().busy(); }

  // devices-calibrate: a finished calibration on the simulated rig with injected errors (three
  // controllers turned, every controller shifted up to 15 mm), so the corrections and the ghost
  // controllers show.
  std::vector<std::string> extra_captures() const override { return {"devices-calibrate"}; }

  void prepare_extra_capture(const std::string& name) override {
    if (name != "devices-calibrate") return;
    devices::SimConfig sim;
    sim.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
    sim.calibration_rotations_deg["LMC3"] = Eigen::Vector3d(4, 0, 0);
    sim.calibration_rotations_deg["LMC4"] = Eigen::Vector3d(0, 0, -3);
    sim.calibration_random_translation_mm = 15;
    if (const std::string err = vm_.start("sim", sim); !err.empty()) {
      status_.set_status("Devices: " + err, true);
      return;
    }
    const auto dir = capture_scratch_.fresh("calibration");
    if (const std::string err = calibrate_.step().record(dir, {}); !err.empty()) status_.set_status(err, true);
  }

 private:
  void start(const std::string& backend) {
    const std::string err = vm_.start(backend);
    if (!err.empty()) status_.set_status("Devices: " + err, true);
  }

  void draw_toolbar() {
    ImGui::TextUnformatted("Backend");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    if (ImGui::BeginCombo("##backend", backend_choice_ == 0 ? "sim" : backend_choice_ == 1 ? "leapc" : "replay")) {
      if (ImGui::Selectable("sim", backend_choice_ == 0)) backend_choice_ = 0;
      if (devices::leapc_available()) {
        if (ImGui::Selectable("leapc", backend_choice_ == 1)) backend_choice_ = 1;
      } else {
        ImGui::TextDisabled("leapc (built without the Ultraleap SDK)");
      }
      if (ImGui::Selectable("replay", backend_choice_ == 2)) backend_choice_ = 2;
      ImGui::EndCombo();
    }
    if (backend_choice_ == 2) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(260);
      ImGui::InputTextWithHint("##replay", "recording file (.raw.txt)", replay_, sizeof replay_);
    }
    ImGui::SameLine();
    ImGui::TextUnformatted("Layout");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.6F, 0.85F, 1.0F, 1.0F), "%s", vm_.layout().name.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("The layout open in the Layout tab: open, edit or pick a preset there and the rig follows");
    }
    ImGui::SameLine();
    if (ImGui::Button("Save with serials...")) {
      save_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), vm_.layout().name + "-serials.json");
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "Write this layout with every controller's serial in its slot, so each controller returns to "
          "its slot next time");
    }
    if (const auto chosen = save_browser_.draw()) {
      try {
        save_layout(vm_.layout(), *chosen);
        status_.set_status("Saved " + chosen->string() + " with the serial of every assigned controller");
      } catch (const std::exception& e) {
        status_.set_status(e.what(), true);
      }
    }
    ImGui::SameLine();
    if (!vm_.running()) {
      if (ImGui::Button("Start")) start(backend_spec());
    } else {
      if (ImGui::Button("Stop")) vm_.stop();
      ImGui::SameLine();
      ImGui::Text("%s running %.0f s", vm_.backend().c_str(), vm_.running_seconds());
    }
  }

  std::string backend_spec() const {
    if (backend_choice_ == 1) return "leapc";
    if (backend_choice_ == 2) return std::string("replay:") + replay_;
    return "sim";
  }

  void draw_table() {
    const auto& rows = vm_.rows();
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("devices", 12, flags)) return;
    for (const char* h :
         {"", "Serial", "Slot", "Backend", "Model", "Mode", "Status", "Rate", "Hand", "Frame age", "Frames", "Dropped"})
      ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    const auto slots = vm_.slot_choices();
    for (const auto& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const ImVec2 p = ImGui::GetCursorScreenPos();
      ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + 14, p.y + 14),
                                                device_colour_u32(r.colour, r.slot.empty() ? 0.3F : 1.0F));
      ImGui::Dummy(ImVec2(14, 14));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.serial.c_str());
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(90);
      const std::string id = "##slot" + r.serial;
      if (ImGui::BeginCombo(id.c_str(), r.slot.empty() ? "-" : r.slot.c_str())) {
        for (const auto& s : slots) {
          if (ImGui::Selectable(s.c_str(), s == r.slot)) {
            const std::string err = vm_.assign(r.serial, s);
            status_.set_status(err.empty() ? r.serial + " → " + s : err, !err.empty());
          }
        }
        ImGui::EndCombo();
      }
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.backend.c_str());
      ImGui::TableNextColumn();
      if (r.model.empty())
        ImGui::TextDisabled("-");
      else
        ImGui::TextUnformatted(r.model.c_str());
      ImGui::TableNextColumn();
      // The tracking mode the service reports: anything but what the layout implies is a warning
      // in the device messages; here it is just shown.
      if (r.tracking_mode.empty())
        ImGui::TextDisabled("-");
      else
        ImGui::TextUnformatted(r.tracking_mode.c_str());
      ImGui::TableNextColumn();
      if (r.warn)
        ImGui::TextColored(ImVec4(1.0F, 0.55F, 0.3F, 1.0F), "%s", r.status.c_str());
      else
        ImGui::TextUnformatted(r.status.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.0f Hz", r.rate_hz);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.hand_present ? "yes" : "no");
      ImGui::TableNextColumn();
      if (r.age_ms < 0)
        ImGui::TextDisabled("-");
      else
        ImGui::Text("%.0f ms", r.age_ms);
      ImGui::TableNextColumn();
      ImGui::Text("%lld", static_cast<long long>(r.frames));
      ImGui::TableNextColumn();
      ImGui::Text("%lld", static_cast<long long>(r.dropped));
    }
    ImGui::EndTable();
    if (rows.empty()) ImGui::TextDisabled(vm_.running() ? "waiting for devices…" : "no backend running: press Start");
    // A controller the layout points away from the hand shows "no hand" forever: say it is the layout.
    ImGui::PushTextWrapPos(0.0F);
    for (const std::string& w : vm_.layout_warnings())
      ImGui::TextColored(ImVec4(1.0F, 0.55F, 0.3F, 1.0F), "%s", w.c_str());
    ImGui::PopTextWrapPos();
  }

  void draw_recording_row() {
    ImGui::TextUnformatted("Test recording");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    ImGui::InputText("##trial", trial_, sizeof trial_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(260);
    ImGui::InputText("##folder", folder_, sizeof folder_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("s##seconds", &seconds_, 0, 0, "%.0f");
    seconds_ = std::clamp(seconds_, 1.0, 3600.0);
    ImGui::SameLine();
    if (!vm_.recording()) {
      if (ImGui::Button("Record")) {
        const std::string err = vm_.start_recording(folder_, trial_, seconds_);
        if (err.empty())
          status_.set_status("recording " + vm_.recording_trial());
        else
          status_.set_status(err, true);
      }
    } else {
      if (ImGui::Button("Stop recording")) vm_.stop_recording();
    }
    if (auto p = vm_.recording_progress()) {
      ImGui::SameLine();
      if (vm_.recording()) {
        ImGui::Text("%s: %s, %.1f s recorded, %lld frames written, %lld dropped", p->trial.c_str(), p->phase.c_str(),
                    p->recording_s, static_cast<long long>(p->frames_written),
                    static_cast<long long>(p->frames_dropped));
      } else {
        ImGui::TextDisabled("last: %s, %.1f s, %lld frames", p->trial.c_str(), p->recording_s,
                            static_cast<long long>(p->frames_written));
      }
    }
  }

  void draw_live_view() {
    if (vm_.running()) ImGui::TextDisabled("%s", fusion_latency_line(vm_.fusion_stats()).c_str());
    const auto& ghosts = calibrate_.ghosts();
    const std::string caption =
        ghosts.empty()
            ? "World frame (mm), one colour per device; the fused hand thick, fingers by how many controllers "
              "see them (red none, orange 1, yellow 2, green 3+). Drag to orbit, wheel to zoom."
            : "Calibration result: thin outlines = where the layout puts each controller now, bold boxes = "
              "where the calibration puts it, a line joins the two. Drag to orbit, wheel to zoom.";
    draw_live_hands_view("live_canvas", camera_, vm_.layout(), vm_.hands(), caption,
                         vm_.fused() ? &*vm_.fused() : nullptr, ghosts.empty() ? nullptr : &ghosts);
  }

  void handle_shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    if (io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed('Z', false)) calibrate_.undo_shortcut();
  }

  StatusSink& status_;
  CaptureScratch capture_scratch_;  // before vm_ and calibrate_: removed after they stop recording
  DevicesViewModel vm_;
  OrbitCamera camera_;  // starts on the Layout tab's default view, which shows every controller
  std::uint64_t seen_messages_ = 0;
  double seconds_ = DevicesViewModel::kDefaultTrialSeconds;
  bool auto_started_ = false;
  bool fallback_pending_ = false;
  int backend_choice_ = 0;
  char replay_[512] = "";
  char trial_[80] = "";
  char folder_[512] = "";
  FileBrowser save_browser_{"Save layout with serials", ".json"};
  DevicesCalibratePanel calibrate_;  // after vm_: its step records through the same rig
};

}  // namespace

std::unique_ptr<Tab> make_devices_tab(StatusSink& status, WorkbenchContext& context) {
  return std::make_unique<DevicesTab>(status, context);
}

}  // namespace lmc::ui
