// The Devices tab (issue #5): every connected controller (or the simulated rig) with serial,
// slot (assign by dropdown), backend, status, rate, hand present and latest frame age; a live 3-D
// view of every device's hand realigned into the world frame, one colour per device, so a
// misplaced controller shows at a glance; start/stop of a test recording. All logic lives in
// devices/view/devices_view_model.h; this file only draws (ImGui draw list + the view model's own
// small perspective camera, independent of the Layout tab's GL renderer).
#include "ui/tabs/devices/devices_tab.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/common/paths.h"
#include "core/io/layout_json.h"
#include "devices/source_factory.h"
#include "devices/view/devices_view_model.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {
namespace {

using devices::DevicesViewModel;

ImU32 colour_u32(int index, float alpha = 1.0F) {
  const auto c = devices::device_colour(index);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], alpha));
}

Layout initial_layout() {
  try {
    return load_layout_or_preset("paper-initial");
  } catch (const std::exception&) {
    Layout l;
    l.name = "four devices";
    for (int i = 0; i < 4; ++i) {
      LayoutDevice d;
      d.slot = "LMC" + std::to_string(i + 1);
      d.pose.x_mm = i % 2 == 0 ? -60 : 60;
      d.pose.z_mm = i < 2 ? 60 : -60;
      l.devices.push_back(d);
    }
    return l;
  }
}

constexpr const char* kPresets[] = {"paper-initial", "paper-optimized", "paper-optimized-as-processed"};

class DevicesTab final : public Tab {
 public:
  explicit DevicesTab(StatusSink& status) : status_(status), vm_(initial_layout()) {
    const std::string tmp = (sessions_dir() / "test-recordings").string();
    std::snprintf(folder_, sizeof folder_, "%s", tmp.c_str());
    std::snprintf(trial_, sizeof trial_, "%s", "test_trial_1");
  }

  void update() override {
    if (!vm_.running()) return;
    vm_.refresh();
    // With the SDK present, LeapC is tried first; without controllers the simulated rig takes over.
    if (fallback_pending_ && vm_.running_seconds() > 3.0) {
      fallback_pending_ = false;
      if (vm_.rows().empty()) {
        status_.set_status("no controller found: running the simulated rig");
        start("sim");
      }
    }
    if (was_recording_ && !vm_.recording()) {
      was_recording_ = false;
      const std::string& last = vm_.messages().empty() ? std::string() : vm_.messages().back();
      status_.set_status(last, last.find("recorded") != 0);
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
    const float log_width = std::max(260.0F, avail.x * 0.28F);
    ImGui::BeginChild("live_view", ImVec2(avail.x - log_width - 8.0F, avail.y), true,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    draw_live_view();
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginChild("device_log", ImVec2(0, avail.y), true);
    ImGui::TextDisabled("Device messages");
    for (const auto& m : vm_.messages()) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0F);
    ImGui::EndChild();
  }

  int prepare_for_capture() override {
    if (!vm_.running() || vm_.backend() != "sim") {
      auto_started_ = true;
      start("sim");
    }
    return 30;
  }

  bool busy_for_capture() const override { return vm_.running() && !vm_.all_streaming(); }

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
    ImGui::SetNextItemWidth(220);
    if (ImGui::BeginCombo("##layout", vm_.layout().name.c_str())) {
      for (const char* preset : kPresets) {
        if (ImGui::Selectable(preset, vm_.layout().name == preset)) {
          try {
            const bool was_running = vm_.running();
            vm_.set_layout(load_layout_or_preset(preset));
            if (was_running) start(backend_spec());
          } catch (const std::exception& e) {
            status_.set_status(e.what(), true);
          }
        }
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Open...")) layout_browser_.open(FileBrowser::Mode::kOpen, assets_dir() / "layouts");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Use a layout file of your own (its serials bind controllers to slots)");
    ImGui::SameLine();
    if (ImGui::Button("Save with serials...")) {
      save_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), vm_.layout().name + "-serials.json");
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Write this layout with every controller's serial in its slot, so each controller returns to "
                        "its slot next time");
    }
    if (const auto chosen = layout_browser_.draw()) use_layout_file(*chosen);
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

  void use_layout_file(const std::filesystem::path& path) {
    try {
      const bool was_running = vm_.running();
      vm_.set_layout(load_layout(path));
      status_.set_status("Devices use layout " + path.string());
      if (was_running) start(backend_spec());
    } catch (const std::exception& e) {
      status_.set_status(e.what(), true);
    }
  }

  std::string backend_spec() const {
    if (backend_choice_ == 1) return "leapc";
    if (backend_choice_ == 2) return std::string("replay:") + replay_;
    return "sim";
  }

  void draw_table() {
    const auto& rows = vm_.rows();
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("devices", 10, flags)) return;
    for (const char* h : {"", "Serial", "Slot", "Backend", "Status", "Rate", "Hand", "Frame age", "Frames", "Dropped"})
      ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    const auto slots = vm_.slot_choices();
    for (const auto& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const ImVec2 p = ImGui::GetCursorScreenPos();
      ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + 14, p.y + 14),
                                                colour_u32(r.colour, r.slot.empty() ? 0.3F : 1.0F));
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
      if (r.warn) ImGui::TextColored(ImVec4(1.0F, 0.55F, 0.3F, 1.0F), "%s", r.status.c_str());
      else ImGui::TextUnformatted(r.status.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.0f Hz", r.rate_hz);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.hand_present ? "yes" : "no");
      ImGui::TableNextColumn();
      if (r.age_ms < 0) ImGui::TextDisabled("-");
      else ImGui::Text("%.0f ms", r.age_ms);
      ImGui::TableNextColumn();
      ImGui::Text("%lld", static_cast<long long>(r.frames));
      ImGui::TableNextColumn();
      ImGui::Text("%lld", static_cast<long long>(r.dropped));
    }
    ImGui::EndTable();
    if (rows.empty()) ImGui::TextDisabled(vm_.running() ? "waiting for devices…" : "no backend running: press Start");
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
    if (!vm_.recording()) {
      if (ImGui::Button("Record")) {
        const std::string err = vm_.start_recording(folder_, trial_);
        if (err.empty()) {
          was_recording_ = true;
          status_.set_status(std::string("recording ") + trial_);
        } else {
          status_.set_status(err, true);
        }
      }
    } else {
      if (ImGui::Button("Stop recording")) {
        const std::string summary = vm_.stop_recording();
        was_recording_ = false;
        status_.set_status(summary, summary.rfind("recorded", 0) != 0);
      }
      if (auto st = vm_.recording_status()) {
        ImGui::SameLine();
        ImGui::Text("%lld frames written, %lld dropped", static_cast<long long>(st->frames_written),
                    static_cast<long long>(st->frames_dropped));
      }
    }
  }

  void draw_live_view() {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    ImGui::InvisibleButton("live_canvas", ImVec2(std::max(size.x, 1.0F), std::max(size.y, 1.0F)));
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
      const ImVec2 d = ImGui::GetIO().MouseDelta;
      camera_.yaw_deg -= d.x * 0.3;
      camera_.pitch_deg = std::clamp(camera_.pitch_deg + d.y * 0.3, -10.0, 89.0);
    }
    if (ImGui::IsItemHovered() && ImGui::GetIO().MouseWheel != 0)
      camera_.distance_mm = std::clamp(camera_.distance_mm * std::pow(0.9, ImGui::GetIO().MouseWheel), 200.0, 3000.0);
    dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(24, 26, 30, 255));
    auto proj = [&](const Eigen::Vector3d& w) { return camera_.project(w, origin.x, origin.y, size.x, size.y); };
    auto line = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, ImU32 col, float thickness) {
      auto pa = proj(a);
      auto pb = proj(b);
      if (pa && pb)
        dl->AddLine(ImVec2(static_cast<float>(pa->x()), static_cast<float>(pa->y())),
                    ImVec2(static_cast<float>(pb->x()), static_cast<float>(pb->y())), col, thickness);
    };
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    // The table top (y = 0), 50 mm grid, world axes at the origin.
    for (int k = -300; k <= 300; k += 50) {
      const ImU32 col = k == 0 ? IM_COL32(90, 90, 100, 255) : IM_COL32(55, 58, 65, 255);
      line({static_cast<double>(k), 0, -300}, {static_cast<double>(k), 0, 300}, col, 1.0F);
      line({-300, 0, static_cast<double>(k)}, {300, 0, static_cast<double>(k)}, col, 1.0F);
    }
    line({0, 0, 0}, {60, 0, 0}, IM_COL32(220, 80, 80, 255), 2.0F);
    line({0, 0, 0}, {0, 60, 0}, IM_COL32(80, 220, 80, 255), 2.0F);
    line({0, 0, 0}, {0, 0, 60}, IM_COL32(80, 120, 240, 255), 2.0F);
    // Each controller: its 80 × 30 mm top face where the layout puts it, plus a short view axis.
    const Layout& layout = vm_.layout();
    for (size_t i = 0; i < layout.devices.size(); ++i) {
      const LayoutDevice& d = layout.devices[i];
      const ImU32 col = colour_u32(static_cast<int>(i));
      const Eigen::Vector3d c[4] = {d.to_world({-40, 0, -15}), d.to_world({40, 0, -15}), d.to_world({40, 0, 15}),
                                    d.to_world({-40, 0, 15})};
      for (int k = 0; k < 4; ++k) line(c[k], c[(k + 1) % 4], col, 2.0F);
      line(d.to_world({0, 0, 0}), d.to_world({0, 40, 0}), col, 1.0F);
      if (auto p = proj(d.to_world({0, 0, 25})))
        dl->AddText(ImVec2(static_cast<float>(p->x()) - 14, static_cast<float>(p->y())), col, d.slot.c_str());
    }
    // Every device's hand in the world frame: where the hands disagree, a device is misplaced.
    for (const auto& h : vm_.hands()) {
      const ImU32 col = colour_u32(h.colour);
      for (const auto& [a, b] : devices::hand_bones())
        line(h.world[static_cast<size_t>(a)], h.world[static_cast<size_t>(b)], col, 2.0F);
      if (auto p = proj(h.world[kPalm]))
        dl->AddCircleFilled(ImVec2(static_cast<float>(p->x()), static_cast<float>(p->y())), 4.0F, col);
    }
    dl->PopClipRect();
    dl->AddText(ImVec2(origin.x + 8, origin.y + 6), IM_COL32(200, 200, 210, 255),
                "World frame (mm), one colour per device. Drag to orbit, wheel to zoom.");
  }

  StatusSink& status_;
  DevicesViewModel vm_;
  devices::ViewCamera camera_;
  bool auto_started_ = false;
  bool fallback_pending_ = false;
  bool was_recording_ = false;
  int backend_choice_ = 0;
  char replay_[512] = "";
  char trial_[80] = "";
  char folder_[512] = "";
  FileBrowser layout_browser_{"Open layout", ".json"};
  FileBrowser save_browser_{"Save layout with serials", ".json"};
};

}  // namespace

std::unique_ptr<Tab> make_devices_tab(StatusSink& status) { return std::make_unique<DevicesTab>(status); }

}  // namespace lmc::ui
