#include "ui/model/devices/devices_view_model.h"

#include <Eigen/Geometry>

#include <algorithm>

#include "core/visibility/blind_controllers.h"
#include "devices/device_hub.h"
#include "devices/record/trial_engine.h"

namespace lmc::ui {
namespace {
constexpr double kStalledMs = 500.0;  // no frame for this long while connected: something is wrong

std::string blind_controller_words(HiddenReason reason) {
  switch (reason) {
    case HiddenReason::kWrongApproach:
      return "it faces away from the hand (the hand comes at it from behind)";
    case HiddenReason::kOutOfRange:
      return "the hand is beyond its range";
    case HiddenReason::kOutOfView:
      return "the hand is outside its field of view";
    case HiddenReason::kBehindPalm:
    case HiddenReason::kBehindFinger:
      return "the hand hides every finger from it";
    case HiddenReason::kNoHand:
    case HiddenReason::kVisible:
      break;
  }
  return "it sees no finger";
}

}  // namespace

DevicesViewModel::DevicesViewModel(LiveRig& rig) : rig_(rig) {}

std::string DevicesViewModel::start(const std::string& backend, const devices::SimConfig& sim) {
  rows_.clear();
  hands_.clear();
  all_streaming_ = false;
  return rig_.start(backend, sim);
}

void DevicesViewModel::stop() {
  rig_.stop();
  rows_.clear();
  hands_.clear();
  all_streaming_ = false;
}

void DevicesViewModel::refresh() {
  rig_.poll();
  if (!warned_layout_ || !(*warned_layout_ == rig_.layout())) {
    warned_layout_ = rig_.layout();
    layout_warnings_.clear();
    blind_slots_.clear();
    for (const BlindController& b : blind_controllers(*warned_layout_)) {
      blind_slots_.push_back(b.device);
      layout_warnings_.push_back(b.slot + " cannot see the hand: in all ten reference hand poses " +
                                 blind_controller_words(b.reason) + ". Its \"no hand\" comes from layout '" +
                                 warned_layout_->name + "'; move or turn it in the Layout tab.");
    }
  }
  rows_.clear();
  hands_.clear();
  fused_.reset();
  fusion_stats_ = {};
  all_streaming_ = false;
  const devices::DeviceHub* hub = rig_.hub();
  if (hub == nullptr) return;
  if (const devices::LiveFusion* fusion = rig_.fusion()) {
    fused_ = fusion->latest();
    fusion_stats_ = fusion->stats();
  }
  const devices::HubSnapshot snap = hub->snapshot();
  const Layout& hub_layout = hub->layout();
  int streaming_slots = 0;
  for (const devices::DeviceStatus& s : snap.devices) {
    DeviceRow r;
    r.serial = s.serial;
    r.slot = s.slot;
    r.slot_index = s.slot_index;
    r.backend = s.backend;
    r.model = s.model;
    r.model_warning = s.model_warning;
    r.tracking_mode = s.tracking_mode;
    r.rate_hz = s.rate_hz;
    r.age_ms = s.latest_frame_age_ms;
    r.hand_present = s.hand_present;
    r.frames = s.frames_received;
    r.dropped = s.frames_dropped + s.frames_dropped_recorder;
    r.colour = s.slot_index >= 0 ? s.slot_index : 7;
    if (!s.connected)
      r.status = "disconnected";
    else if (s.slot_index < 0)
      r.status = "unassigned";
    else if (s.frames_received == 0)
      r.status = "waiting";
    else if (r.age_ms > kStalledMs)
      r.status = "stalled";
    else
      r.status = s.hand_present ? "streaming" : "no hand";
    // The study saw 11–34 Hz with four devices; below that, suspect USB bandwidth or power.
    r.warn =
        r.status == "disconnected" || r.status == "stalled" || (s.connected && s.frames_received > 0 && r.rate_hz < 10);
    r.warn = r.warn || std::find(blind_slots_.begin(), blind_slots_.end(), s.slot_index) != blind_slots_.end();
    r.warn = r.warn || !r.model_warning.empty();
    if (s.slot_index >= 0 && s.connected && s.frames_received > 0 && r.age_ms <= kStalledMs) ++streaming_slots;
    if (auto h = live_hand(s, hub_layout)) hands_.push_back(std::move(*h));
    rows_.push_back(std::move(r));
  }
  all_streaming_ = streaming_slots >= hub_layout.device_count() && running_seconds() >= 1.2;
}

std::vector<std::string> DevicesViewModel::slot_choices() const {
  std::vector<std::string> out;
  for (const auto& d : layout().devices) out.push_back(d.slot);
  return out;
}

std::string DevicesViewModel::assign(const std::string& serial, const std::string& slot) {
  return rig_.assign(serial, slot);
}

std::string DevicesViewModel::start_recording(const std::filesystem::path& dir, const std::string& trial,
                                              double seconds) {
  return rig_.start_trial(dir, trial, seconds);
}

std::optional<RecordingProgress> DevicesViewModel::recording_progress() const {
  const auto& snap = rig_.trial().snapshot();
  if (!snap) return std::nullopt;
  RecordingProgress p;
  p.trial = snap->trial.empty() ? rig_.trial_name() : snap->trial;
  p.phase = devices::trial_phase_name(snap->phase);
  p.recording_s = snap->recording_s;
  p.remaining_s = snap->remaining_s;
  p.frames_written = snap->recorder.frames_written;
  p.frames_dropped = snap->recorder.frames_dropped;
  return p;
}

}  // namespace lmc::ui
