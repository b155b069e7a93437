#include "devices/device_hub.h"

#include <algorithm>
#include <utility>

#include "core/common/error.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/layout/sensor_catalogue.h"

namespace lmc::devices {
namespace {
constexpr std::int64_t kRateWindowNs = 1'000'000'000;
}

DeviceHub::DeviceHub(Layout layout, HubOptions options) : layout_(std::move(layout)), options_(std::move(options)) {
  if (!options_.clock) options_.clock = host_now_ns;
}

DeviceHub::~DeviceHub() {
  stop();
}

void DeviceHub::add_source(std::unique_ptr<FrameSource> source) {
  std::lock_guard lock(mutex_);
  sources_.push_back(std::move(source));
}

void DeviceHub::start() {
  std::vector<FrameSource*> to_start;
  {
    std::lock_guard lock(mutex_);
    if (running_) return;
    running_ = true;
    for (auto& s : sources_) to_start.push_back(s.get());
  }
  for (auto* s : to_start) s->start(*this);
}

void DeviceHub::stop() {
  std::vector<FrameSource*> to_stop;
  {
    std::lock_guard lock(mutex_);
    if (!running_) return;
    running_ = false;
    for (auto& s : sources_) to_stop.push_back(s.get());
  }
  // Outside the lock: a source's thread may be inside on_frame waiting for the mutex.
  for (auto* s : to_stop) s->stop();
}

bool DeviceHub::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

bool DeviceHub::sources_finished() const {
  std::lock_guard lock(mutex_);
  if (sources_.empty()) return false;
  return std::all_of(sources_.begin(), sources_.end(), [](const auto& s) { return s->finished(); });
}

std::vector<std::string> DeviceHub::backends() const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> out;
  for (const auto& s : sources_) out.push_back(s->backend_name());
  return out;
}

void DeviceHub::set_consumer(FrameConsumer* consumer) {
  std::lock_guard consumer_lock(consumer_mutex_);
  consumer_ = consumer;
}

void DeviceHub::add_tap(FrameTap* tap) {
  if (tap == nullptr) return;
  std::lock_guard tap_lock(tap_mutex_);
  if (std::find(taps_.begin(), taps_.end(), tap) == taps_.end()) taps_.push_back(tap);
}

void DeviceHub::remove_tap(FrameTap* tap) {
  std::lock_guard tap_lock(tap_mutex_);
  std::erase(taps_, tap);
}

std::string DeviceHub::label(const DeviceStatus& s) {
  return s.slot.empty() ? "device " + s.serial : s.slot + " (" + s.serial + ")";
}

void DeviceHub::message_locked(std::string text) {
  messages_.push_back(std::move(text));
  while (messages_.size() > options_.max_messages) messages_.pop_front();
}

DeviceHub::Device& DeviceHub::device_for_locked(const std::string& serial) {
  for (auto& d : devices_)
    if (d.status.serial == serial) return d;
  Device& d = devices_.emplace_back();
  d.status.serial = serial;
  const int bound = layout_.find_serial(serial);
  if (bound >= 0) {
    d.status.slot_index = bound;
    d.status.slot = layout_.devices[static_cast<size_t>(bound)].slot;
  } else {
    try_auto_assign_locked(d);
  }
  return d;
}

void DeviceHub::check_model_locked(Device& d) {
  DeviceStatus& s = d.status;
  const std::string before = s.model_warning;
  s.model_warning.clear();
  if (s.slot_index >= 0 && s.product_id != 0) {
    const LayoutDevice& ld = layout_.devices[static_cast<size_t>(s.slot_index)];
    try {
      s.model_warning = slot_model_mismatch(ld.slot, ld.model, s.product_id, sensor_catalogue());
    } catch (const Error& e) {
      s.model_warning = std::string("cannot check ") + ld.slot + "'s model: " + e.what();
    }
  }
  if (!s.model_warning.empty() && s.model_warning != before) message_locked("warning: " + s.model_warning);
}

void DeviceHub::try_auto_assign_locked(Device& d) {
  if (!options_.auto_assign) return;
  for (size_t i = 0; i < layout_.devices.size(); ++i) {
    if (layout_.devices[i].serial) continue;
    const bool taken = std::any_of(devices_.begin(), devices_.end(), [&](const Device& o) {
      return &o != &d && o.status.slot_index == static_cast<int>(i);
    });
    if (taken) continue;
    d.status.slot_index = static_cast<int>(i);
    d.status.slot = layout_.devices[i].slot;
    d.auto_assigned = true;
    return;
  }
}

std::string DeviceHub::assign(const std::string& serial, const std::string& slot) {
  std::lock_guard lock(mutex_);
  const int index = layout_.find_slot(slot);
  if (index < 0) return "no slot named '" + slot + "' in layout '" + layout_.name + "'";
  Device* target = nullptr;
  for (auto& d : devices_)
    if (d.status.serial == serial) target = &d;
  if (target == nullptr) return "no device with serial '" + serial + "'";
  for (auto& d : devices_) {
    if (&d != target && d.status.slot_index == index) {
      d.status.slot_index = -1;
      d.status.slot.clear();
    }
  }
  // The layout remembers the binding so a re-plug lands in the same slot.
  for (auto& ld : layout_.devices)
    if (ld.serial == serial) ld.serial.reset();
  layout_.devices[static_cast<size_t>(index)].serial = serial;
  target->status.slot_index = index;
  target->status.slot = slot;
  target->auto_assigned = false;
  message_locked(serial + " assigned to " + slot);
  check_model_locked(*target);
  return {};
}

void DeviceHub::unassign(const std::string& serial) {
  std::lock_guard lock(mutex_);
  for (auto& ld : layout_.devices)
    if (ld.serial == serial) ld.serial.reset();
  for (auto& d : devices_) {
    if (d.status.serial == serial) {
      d.status.slot_index = -1;
      d.status.slot.clear();
    }
  }
}

std::vector<std::pair<std::string, std::string>> DeviceHub::serial_to_slot() const {
  std::lock_guard lock(mutex_);
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& d : devices_)
    if (d.status.slot_index >= 0) out.emplace_back(d.status.serial, d.status.slot);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return out;
}

void DeviceHub::on_device_event(const DeviceEvent& event) {
  int device_id = 0;
  std::string slot;
  {
    std::lock_guard lock(mutex_);
    if (event.info.serial.empty()) {
      if (!event.message.empty()) message_locked(event.message);
    } else {
      Device& d = device_for_locked(event.info.serial);
      DeviceStatus& s = d.status;
      switch (event.kind) {
        case DeviceEventKind::kAppeared:
          if (!event.info.backend.empty()) s.backend = event.info.backend;
          if (!event.info.model.empty()) s.model = event.info.model;
          if (event.info.product_id != 0) s.product_id = event.info.product_id;
          if (!event.info.tracking_mode.empty()) s.tracking_mode = event.info.tracking_mode;
          if (!s.connected && s.disconnects > 0) {
            message_locked(label(s) + " reconnected");
          } else if (d.auto_assigned && s.backend != "sim") {
            // USB order is not table order: say that the slot is a guess until someone confirms it.
            message_locked(label(s) + " connected (" + s.backend +
                           "); its slot was given in order of appearance: "
                           "check it is that controller, or pick its slot, then save the layout with its serials");
          } else {
            message_locked(label(s) + " connected (" + s.backend + ")");
          }
          s.connected = true;
          if (s.slot_index < 0) try_auto_assign_locked(d);
          if (s.slot_index < 0) message_locked("serial " + s.serial + " is not in the layout: assign it to a slot");
          check_model_locked(d);
          break;
        case DeviceEventKind::kLost:
          if (s.connected) ++s.disconnects;
          s.connected = false;
          s.hand_present = false;
          message_locked(label(s) + " disconnected" + (event.message.empty() ? "" : ": " + event.message));
          break;
        case DeviceEventKind::kFailure:
          message_locked(label(s) + " failure: " + event.message);
          break;
        case DeviceEventKind::kDroppedFrames:
          s.frames_dropped += event.count;
          break;
        case DeviceEventKind::kNotice:
          message_locked(label(s) + ": " + event.message);
          break;
        case DeviceEventKind::kTrackingMode:
          s.tracking_mode = event.info.tracking_mode;
          message_locked(label(s) + " tracks in " + s.tracking_mode + " mode" +
                         (event.message.empty() ? "" : ": " + event.message));
          break;
      }
      device_id = s.slot_index + 1;
      slot = s.slot;
    }
  }
  std::lock_guard consumer_lock(consumer_mutex_);
  if (consumer_ != nullptr) consumer_->device_event(event, device_id, slot);
}

void DeviceHub::on_frame(const SourceFrame& frame) {
  HandFrame out = frame.frame;
  {
    std::lock_guard lock(mutex_);
    Device& d = device_for_locked(frame.serial);
    DeviceStatus& s = d.status;
    if (!s.connected) {
      s.connected = true;  // a source that streams without announcing (replay) is connected
      if (s.slot_index < 0) try_auto_assign_locked(d);
    }
    ++s.frames_received;
    if (d.last_frame_id >= 0 && frame.frame.frame_id > d.last_frame_id + 1)
      s.frames_dropped += frame.frame.frame_id - d.last_frame_id - 1;
    d.last_frame_id = frame.frame.frame_id;
    d.last_receive_ns = frame.host_receive_ns;
    d.recent_ns[d.recent_head] = frame.host_receive_ns;
    d.recent_head = (d.recent_head + 1) % d.recent_ns.size();
    d.recent_count = std::min(d.recent_count + 1, d.recent_ns.size());
    s.hand_present = frame.frame.hand_present;
    if (frame.hand_type != HandType::kUnknown) s.hand_type = frame.hand_type;
    if (frame.other_side_hand) ++s.frames_other_side_hand;
    out.device_id = s.slot_index + 1;
    s.latest = out;
    if (s.slot_index < 0) return;  // unassigned devices are shown, never recorded into a slot
  }
  bool accepted = true;
  {
    std::lock_guard consumer_lock(consumer_mutex_);
    if (consumer_ != nullptr) {
      accepted = consumer_->offer(out, frame.host_receive_ns, options_.backpressure);
      if (accepted && frame.other_side_hand) consumer_->other_side_hand(out.device_id, frame.host_receive_ns);
    }
  }
  if (!accepted) {
    std::lock_guard lock(mutex_);
    ++device_for_locked(frame.serial).status.frames_dropped_recorder;
  }
  // After the recorder: the live view never delays a frame on its way to the disk.
  std::lock_guard tap_lock(tap_mutex_);
  for (FrameTap* t : taps_) t->tap(out);
}

HubSnapshot DeviceHub::snapshot() const {
  HubSnapshot snap;
  const std::int64_t now = options_.clock();
  snap.host_time_ns = now;
  std::lock_guard lock(mutex_);
  // Each source's device clock at `now`, read once per snapshot; devices find theirs by backend.
  struct Clock {
    std::string backend;
    std::optional<std::int64_t> us, uncertainty_us;
  };
  std::vector<Clock> clocks;
  for (const auto& source : sources_) {
    const std::optional<std::int64_t> us = source->device_clock_us(now);
    clocks.push_back({source->backend_name(), us, source->device_clock_uncertainty_us()});
  }
  for (const auto& ld : layout_.devices) snap.slots.push_back(ld.slot);
  for (const auto& d : devices_) {
    DeviceStatus s = d.status;
    if (s.frames_received > 0) {
      s.latest_frame_age_ms = static_cast<double>(now - d.last_receive_ns) / 1e6;
      s.latest_host_receive_ns = d.last_receive_ns;
      // Rate: frames whose receive time lies in the last second before `now`.
      int count = 0;
      for (size_t k = 0; k < d.recent_count; ++k) {
        const size_t idx = (d.recent_head + d.recent_ns.size() - 1 - k) % d.recent_ns.size();
        if (now - d.recent_ns[idx] > kRateWindowNs) break;
        ++count;
      }
      s.rate_hz = count;
    }
    for (const Clock& clock : clocks) {
      if (clock.backend != s.backend || !clock.us) continue;
      s.device_clock_us = clock.us;
      s.device_clock_uncertainty_us = clock.uncertainty_us;
      break;
    }
    if (s.slot_index < 0) snap.unassigned_serials.push_back(s.serial);
    snap.devices.push_back(std::move(s));
  }
  std::stable_sort(snap.devices.begin(), snap.devices.end(), [](const DeviceStatus& a, const DeviceStatus& b) {
    const int ka = a.slot_index < 0 ? 1000 : a.slot_index;
    const int kb = b.slot_index < 0 ? 1000 : b.slot_index;
    return ka < kb;
  });
  return snap;
}

std::vector<std::string> DeviceHub::take_messages() {
  std::lock_guard lock(mutex_);
  std::vector<std::string> out(messages_.begin(), messages_.end());
  messages_.clear();
  return out;
}

}  // namespace lmc::devices
