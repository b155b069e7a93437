#include "devices/record/recorder.h"

#include <chrono>
#include <utility>

#include "core/common/error.h"
#include "core/io/atomic_write.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/host_clock.h"
#include "devices/record/trial_name.h"

namespace lmc::devices {
namespace {
constexpr size_t kWriteChunkBytes = 1 << 20;
}

const char* recorder_state_name(RecorderState s) {
  switch (s) {
    case RecorderState::kIdle:
      return "idle";
    case RecorderState::kRecording:
      return "recording";
    case RecorderState::kStopped:
      return "stopped";
    case RecorderState::kFailed:
      return "failed";
    case RecorderState::kAborted:
      return "aborted";
  }
  return "?";
}

TrialFiles checked_trial_files(const std::filesystem::path& dir, const std::string& trial) {
  require_valid_trial_name(trial);  // a name from outside becomes a file name only after this
  return trial_files(dir, trial);
}

Recorder::Recorder(RecorderConfig config)
    : config_(std::move(config)), queue_(config_.queue_capacity == 0 ? 1 : config_.queue_capacity) {
  if (config_.flush_interval_ms <= 0 || config_.flush_interval_ms > 1000) config_.flush_interval_ms = 1000;
  for (auto& t : latest_offered_ns_) t.store(std::numeric_limits<std::int64_t>::min());
}

Recorder::~Recorder() {
  stop_requested_ = true;
  if (thread_.joinable()) {
    thread_.request_stop();
    wake_writer();  // the writer's wait has no stop callback (run())
    thread_.join();
  }
}

void Recorder::start() {
  if (started_.exchange(true)) throw Error("recorder already started");
  paths_ = checked_trial_files(config_.output_dir, config_.trial);
  std::error_code ec;
  std::filesystem::create_directories(config_.output_dir, ec);
  if (ec) throw Error(ErrorLocation(config_.output_dir.string()), "cannot create output folder: " + ec.message());
  sink_ = config_.open_sink ? config_.open_sink(paths_.recording) : open_file_sink(paths_.recording);
  if (!sink_) throw Error(ErrorLocation(paths_.recording.string()), "cannot create recording file");
  host_start_utc_ = utc_now_iso8601();
  host_start_ns_ = host_now_ns();
  if (!sink_->write(lmc_recording_header(RecordingKind::kRaw)))
    throw Error(ErrorLocation(paths_.recording.string()), "cannot write recording header: " + sink_->error());
  // A sidecar exists from the first second on, so even a crashed session says what it was.
  write_file_atomically(paths_.sidecar, recorder_sidecar_to_json(sidecar("recording")).dump(2) + "\n");
  thread_ = std::jthread([this](std::stop_token stop) { writer_main(std::move(stop)); });
}

void Recorder::open_window(std::int64_t from_ns, std::int64_t until_ns) {
  {
    std::lock_guard lock(stats_mutex_);
    window_from_utc_ = utc_now_iso8601();
  }
  std::lock_guard lock(producer_mutex_);
  window_until_ns_ = until_ns;
  window_from_ns_ = from_ns;
  // Go is an instant taken a moment before this call: a frame received after that instant but
  // offered before the window opened was held back, and belongs to the trial.
  for (const QueuedFrame& queued : held_before_go_) {
    if (queued.host_receive_ns < from_ns) continue;
    before_window_.fetch_sub(1);
    if (queued.host_receive_ns >= until_ns) {
      after_window_.fetch_add(1);
      continue;
    }
    if (!queue_.try_push(queued)) {
      dropped_.fetch_add(1);
      std::lock_guard stats_lock(stats_mutex_);
      ++stats_[queued.frame.device_id].frames_dropped_queue;
    }
  }
  if (!held_before_go_.empty()) wake_writer();
  held_before_go_.clear();
}

std::string Recorder::window_from_utc() const {
  std::lock_guard lock(stats_mutex_);
  return window_from_utc_;
}

std::vector<int> Recorder::devices_behind(std::int64_t host_ns) const {
  std::vector<int> behind;
  for (int id = 1; id <= kTrackedDevices; ++id) {
    const std::int64_t latest = latest_offered_ns_[static_cast<size_t>(id)].load();
    if (latest != std::numeric_limits<std::int64_t>::min() && latest < host_ns) behind.push_back(id);
  }
  return behind;
}

void Recorder::note_streams_behind_end(std::vector<std::string> slots) {
  std::lock_guard lock(stats_mutex_);
  streams_behind_end_ = std::move(slots);
}

bool Recorder::offer(const HandFrame& frame, std::int64_t host_receive_ns, bool may_wait) {
  if (!started_) {
    dropped_.fetch_add(1);
    return false;
  }
  // One device's frames arrive in order from its source's thread: a store keeps the latest (also
  // once the recorder failed: the end of the trial still waits for the streams to pass it).
  if (frame.device_id >= 1 && frame.device_id <= kTrackedDevices)
    latest_offered_ns_[static_cast<size_t>(frame.device_id)].store(host_receive_ns, std::memory_order_relaxed);
  QueuedFrame queued{frame, host_receive_ns};
  std::unique_lock lock(producer_mutex_);
  if (config_.wait_for_go) {
    // Outside the trial (the countdown, or after its planned end): taken, not written, not lost.
    const std::int64_t from = window_from_ns_.load();
    if (host_receive_ns < from) {
      before_window_.fetch_add(1);
      if (from == kClosed) {
        // Before go, the latest few are held: go may turn out to precede them (open_window).
        held_before_go_.push_back(queued);
        if (held_before_go_.size() > kHeldBeforeGo) held_before_go_.pop_front();
      }
      return true;
    }
    if (host_receive_ns >= window_until_ns_.load()) {
      after_window_.fetch_add(1);
      return true;
    }
  }
  // A frame of the trial that a failed or stopping recorder cannot write is lost, and counted so;
  // one outside the trial (above) is not.
  if (failed_.load(std::memory_order_relaxed) || stop_requested_.load(std::memory_order_relaxed)) {
    dropped_.fetch_add(1);
    return false;
  }
  bool pushed = queue_.try_push(queued);
  while (!pushed && may_wait && !failed_.load() && !stop_requested_.load()) {
    // Full: wait for the writer to take frames (it notifies room_ when a producer waits). The
    // writer never takes producer_mutex_, so a notification may come just before this wait; the
    // timeout bounds that case, and notices a failure or a stop.
    producers_waiting_.fetch_add(1);
    room_.wait_for(lock, std::chrono::milliseconds(1));
    producers_waiting_.fetch_sub(1);
    pushed = queue_.try_push(queued);
  }
  if (pushed) wake_writer();
  lock.unlock();
  if (!pushed) {
    dropped_.fetch_add(1);
    std::lock_guard stats_lock(stats_mutex_);
    ++stats_[frame.device_id].frames_dropped_queue;
  }
  return pushed;
}

void Recorder::device_event(const DeviceEvent& event, int device_id, const std::string& slot) {
  std::lock_guard lock(stats_mutex_);
  nlohmann::json e = {{"host_time_utc", utc_now_iso8601()},
                      {"host_ns", event.host_time_ns},
                      {"serial", event.info.serial},
                      {"slot", slot},
                      {"message", event.message}};
  switch (event.kind) {
    case DeviceEventKind::kAppeared:
      e["event"] = "appeared";
      break;
    case DeviceEventKind::kLost:
      e["event"] = "lost";
      break;
    case DeviceEventKind::kFailure:
      e["event"] = "failure";
      break;
    case DeviceEventKind::kDroppedFrames:
      e["event"] = "dropped_frames";
      e["count"] = event.count;
      break;
    case DeviceEventKind::kNotice:
      e["event"] = "notice";
      break;
    case DeviceEventKind::kTrackingMode:
      e["event"] = "tracking_mode";
      break;
  }
  if (!event.info.model.empty()) e["model"] = event.info.model;
  if (!event.info.tracking_mode.empty()) e["tracking_mode"] = event.info.tracking_mode;
  if (device_id > 0) {
    auto& s = stats_[device_id];
    s.device_id = device_id;
    s.slot = slot;
    if (!event.info.serial.empty()) s.serial = event.info.serial;
    if (event.kind == DeviceEventKind::kLost) s.disconnects.push_back(e);
    if (event.kind == DeviceEventKind::kAppeared && !s.disconnects.empty())
      s.disconnects.back()["reconnected_host_time_utc"] = e["host_time_utc"];
    if (!event.info.model.empty()) s.model = event.info.model;
    if (!event.info.tracking_mode.empty()) s.tracking_mode = event.info.tracking_mode;
  }
  if (events_.size() < 10000) events_.push_back(std::move(e));
}

void Recorder::other_side_hand(int device_id, std::int64_t host_receive_ns) {
  // Counted as offer() wrote: rows outside the trial's window are not in the file.
  if (config_.wait_for_go && (host_receive_ns < window_from_ns_.load() || host_receive_ns >= window_until_ns_.load()))
    return;
  std::lock_guard lock(stats_mutex_);
  DeviceRecordStats& s = stats_[device_id];
  s.device_id = device_id;
  ++s.frames_other_side_hand;
}

void Recorder::note_vicon_packet(SidecarViconPacket packet) {
  std::lock_guard lock(stats_mutex_);
  vicon_packets_.push_back(std::move(packet));
}

void Recorder::note_vicon_packet(const nlohmann::json& packet) {
  note_vicon_packet(sidecar_vicon_packet_from_json(packet, "Vicon packet of trial " + config_.trial));
}

void Recorder::note_stopped_by(std::string what) {
  std::lock_guard lock(stats_mutex_);
  stopped_by_ = std::move(what);
}

void Recorder::note_vicon_listen(SidecarViconListen listen) {
  std::lock_guard lock(stats_mutex_);
  vicon_listen_ = std::move(listen);
}

void Recorder::note_ground_truth(SidecarGroundTruth truth) {
  std::lock_guard lock(stats_mutex_);
  ground_truth_ = std::move(truth);
}

void Recorder::note(const std::string& key, nlohmann::json value) {
  std::lock_guard lock(stats_mutex_);
  notes_[key] = std::move(value);
}

void Recorder::fail(const std::string& message) {
  {
    std::lock_guard lock(stats_mutex_);
    if (error_.empty()) error_ = message;
  }
  failed_ = true;
}

void Recorder::write_queued_frame(const QueuedFrame& queued, std::string& buffer, std::vector<PendingRow>& pending) {
  const HandFrame& f = queued.frame;
  append_lmc_row(buffer, f, RecordingKind::kRaw);
  pending.push_back({f.device_id, f.frame_id, f.timestamp_us, f.hand_present, buffer.size()});
}

void Recorder::count_row(const PendingRow& f) {
  DeviceRecordStats& s = stats_[f.device_id];
  s.device_id = f.device_id;
  if (s.frames_written == 0) {
    s.first_timestamp_us = f.timestamp_us;
  } else {
    if (f.timestamp_us - s.last_timestamp_us > config_.gap_threshold_us)
      s.gaps.push_back({s.last_timestamp_us, f.timestamp_us});
    auto it = last_frame_id_.find(f.device_id);
    if (it != last_frame_id_.end() && f.frame_id > it->second + 1) s.frame_id_gaps += f.frame_id - it->second - 1;
  }
  last_frame_id_[f.device_id] = f.frame_id;
  s.last_timestamp_us = f.timestamp_us;
  ++s.frames_written;
  if (f.hand_present) ++s.frames_with_hand;
}

bool Recorder::push_buffer(std::string& buffer, std::vector<PendingRow>& pending) {
  if (buffer.empty() || failed_) return !failed_;
  // Rows count (in the status and the sidecar) only once they reached the file, so "frames
  // written" never overstates: after a failed write, only the complete rows that made it in.
  const std::uint64_t before = sink_->bytes_written();
  const bool ok = sink_->write(buffer);
  const std::uint64_t reached = ok ? buffer.size() : sink_->bytes_written() - before;
  std::int64_t counted = 0;
  {
    std::lock_guard lock(stats_mutex_);
    for (const auto& row : pending) {
      if (row.end > reached) break;
      count_row(row);
      ++counted;
    }
  }
  written_ += counted;
  buffer.clear();
  pending.clear();
  if (!ok) {
    fail("recording stopped: cannot write " + paths_.recording.string() + " (" + sink_->error() +
         "); the rows written before this point are kept");
  }
  return ok;
}

void Recorder::wake_writer() {
  // Taking the writer's lock orders this push before its check for an empty ring: it either sees
  // the frame or is already waiting and gets the notification.
  { std::lock_guard lock(wake_mutex_); }
  wake_.notify_one();
}

void Recorder::writer_main(std::stop_token stop) noexcept {
  try {
    run(stop);
    return;
  } catch (const std::exception& e) {
    fail(std::string("recording stopped: the writer failed (") + e.what() +
         "); the rows written before this point are kept");
  } catch (...) {
    fail("recording stopped: the writer failed (an unknown error); the rows written before this point are kept");
  }
  // Failed: producers drop what they offer from now on; what is queued is discarded, and the
  // file is closed so that what reached it stays readable.
  try {
    QueuedFrame discarded;
    while (queue_.try_pop(discarded)) {
    }
    if (sink_) sink_->close();
  } catch (...) {
    // The failure above is already the recording's error; a second one adds nothing to act on.
  }
}

void Recorder::run(const std::stop_token& stop) {
  std::string buffer;
  buffer.reserve(kWriteChunkBytes + 4096);
  std::vector<PendingRow> pending;
  auto last_push = std::chrono::steady_clock::now();
  const auto interval = std::chrono::milliseconds(config_.flush_interval_ms);
  QueuedFrame queued;
  for (;;) {
    const bool stopping = stop.stop_requested();
    int popped = 0;
    while (queue_.try_pop(queued)) {
      ++popped;
      if (producers_waiting_.load() > 0) room_.notify_all();
      if (failed_) continue;  // keep draining so producers are not stuck; nothing more is written
      write_queued_frame(queued, buffer, pending);
      if (buffer.size() >= kWriteChunkBytes) push_buffer(buffer, pending);
    }
    const auto now = std::chrono::steady_clock::now();
    if (stopping || now - last_push >= interval) {
      if (!failed_) push_buffer(buffer, pending);
      // At least once a second (the flush interval): a deleted file must end the trial, not
      // let it run on as if its rows were kept.
      if (!failed_) {
        if (const std::string why = sink_->lost(); !why.empty())
          fail("recording stopped: " + why + "; the rows written to it went with it, nothing of this trial is kept");
      }
      last_push = now;
    }
    if (stopping && queue_.size_approx() == 0) break;
    if (popped == 0) {
      // Nothing came: sleep until a frame, the next flush or a stop request.
      // A plain timed wait, woken by stop() itself: the stop-token overload registers a
      // stop_callback, and MinGW-w64's libstdc++ (no futex: its semaphores wait on a condition
      // variable) was seen to leave this thread for ever in that callback's deregistration when
      // the stop request ran it at the same moment, with stop() joining it: a hang under Wine.
      std::unique_lock lock(wake_mutex_);
      wake_.wait_until(lock, last_push + interval,
                       [this, &stop] { return queue_.size_approx() > 0 || stop.stop_requested(); });
    }
  }
  if (!failed_) {
    if (!sink_->sync()) fail("recording stopped: " + sink_->error());
  }
  if (!sink_->close() && !failed_) fail("recording stopped: " + sink_->error());
}

RecorderStatus Recorder::stop(const std::vector<std::pair<std::string, std::string>>& serial_to_slot,
                              const std::string& abort_reason) {
  if (!started_) return status();
  stop_requested_ = true;
  if (thread_.joinable()) {
    thread_.request_stop();
    wake_writer();  // the writer's wait has no stop callback (run())
    thread_.join();
  }
  {
    std::lock_guard lock(stats_mutex_);
    // A write error of our own is the first cause and keeps "failed"; otherwise the caller's
    // reason makes the trial "aborted".
    if (!abort_reason.empty() && !failed_ && !aborted_) {
      error_ = abort_reason;
      aborted_ = true;
    }
    host_stop_utc_ = utc_now_iso8601();
    host_stop_ns_ = host_now_ns();
    if (!serial_to_slot.empty()) serial_to_slot_ = serial_to_slot;
    for (const auto& [serial, slot] : serial_to_slot_) {
      const int index = config_.layout.find_slot(slot);
      if (index < 0) continue;
      auto& s = stats_[index + 1];
      s.device_id = index + 1;
      s.slot = slot;
      s.serial = serial;
    }
    for (auto& [id, s] : stats_) {
      if (s.slot.empty() && id >= 1 && id <= config_.layout.device_count())
        s.slot = config_.layout.devices[static_cast<size_t>(id - 1)].slot;
    }
  }
  try {
    const char* state = failed_ ? "failed" : aborted_ ? "aborted" : "completed";
    write_file_atomically(paths_.sidecar, recorder_sidecar_to_json(sidecar(state)).dump(2) + "\n");
  } catch (const std::exception& e) {
    // Never swallowed: with a full disk the sidecar on disk still says "recording"
    // with no frames, so the status must say so even when another error came first.
    const std::string why =
        std::string("cannot write the session sidecar (") + e.what() + "); the sidecar on disk still says 'recording'";
    {
      std::lock_guard lock(stats_mutex_);
      error_ = error_.empty() ? why : error_ + "; and " + why;
    }
    failed_ = true;
  }
  return status();
}

RecorderStatus Recorder::status() const {
  RecorderStatus st;
  st.queue_depth = queue_.size_approx();
  st.frames_written = written_.load();
  st.frames_dropped = dropped_.load();
  std::lock_guard lock(stats_mutex_);
  st.devices = stats_;
  st.error = error_;
  if (failed_)
    st.state = RecorderState::kFailed;
  else if (aborted_)
    st.state = RecorderState::kAborted;
  else if (!started_)
    st.state = RecorderState::kIdle;
  else if (stop_requested_ && !thread_.joinable())
    st.state = RecorderState::kStopped;
  else
    st.state = RecorderState::kRecording;
  return st;
}

namespace {

// A device's counts, gaps and disconnections as the sidecar records them.
SidecarDevice sidecar_device_from_stats(int id, const DeviceRecordStats& s) {
  SidecarDevice d;
  d.device_id = id;
  d.slot = s.slot;
  d.serial = s.serial;
  d.frames_written = s.frames_written;
  d.frames_with_hand = s.frames_with_hand;
  d.frames_dropped_queue = s.frames_dropped_queue;
  d.frame_id_gaps = s.frame_id_gaps;
  d.first_timestamp_us = s.first_timestamp_us;
  d.last_timestamp_us = s.last_timestamp_us;
  d.model = s.model;
  d.tracking_mode = s.tracking_mode;
  d.frames_other_side_hand = s.frames_other_side_hand;
  for (const auto& g : s.gaps) {
    SidecarGap gap;
    gap.from_timestamp_us = g.from_timestamp_us;
    gap.to_timestamp_us = g.to_timestamp_us;
    d.gaps.push_back(gap);
  }
  for (const auto& e : s.disconnects) {
    SidecarDisconnect x;
    x.host_time_utc = e.value("host_time_utc", "");
    x.host_ns = e.value("host_ns", std::int64_t{0});
    x.message = e.value("message", "");
    x.reconnected_host_time_utc = e.value("reconnected_host_time_utc", "");
    x.event = e.value("event", "");
    x.serial = e.value("serial", "");
    x.slot = e.value("slot", "");
    d.disconnects.push_back(std::move(x));
  }
  return d;
}

}  // namespace

RecorderSidecar Recorder::sidecar(const char* state) const {
  std::lock_guard lock(stats_mutex_);
  RecorderSidecar sc;
  sc.trial = config_.trial;
  sc.status = state;
  sc.error = error_;
  sc.stopped_by = stopped_by_;
  sc.software_name = "lmc-workbench";
  sc.software_version = LMC_VERSION;
  sc.backend = config_.backend;
  sc.recording_file = paths_.recording.filename().string();
  sc.recording_format = "raw";
  sc.host_start_utc = host_start_utc_;
  sc.host_stop_utc = host_stop_utc_;
  sc.host_start_ns = host_start_ns_;
  sc.host_stop_ns = host_stop_ns_;
  sc.layout = layout_to_json(config_.layout);
  sc.serial_to_slot = serial_to_slot_;
  for (const auto& [id, s] : stats_) {
    sc.devices.push_back(sidecar_device_from_stats(id, s));
    sc.frames_written += s.frames_written;
  }
  sc.frames_dropped = dropped_.load();
  sc.vicon_packets = vicon_packets_;
  sc.events = events_;
  sc.ground_truth = ground_truth_;
  sc.vicon_listen = vicon_listen_;
  for (const auto& [key, value] : notes_.items()) {
    if (key == "vicon_alignment")
      sc.vicon_alignment = value;
    else if (key == "vicon_trigger_received")
      sc.vicon_trigger_received = value;
    else if (key == "vicon_stop_received")
      sc.vicon_stop_received = value;
    else
      sc.unknown[key] = value;
  }
  if (config_.wait_for_go) {
    nlohmann::json w = config_.trial_window.is_object() ? config_.trial_window : nlohmann::json::object();
    const std::int64_t from = window_from_ns_.load();
    w["go_host_ns"] = from == kClosed ? nlohmann::json(nullptr) : nlohmann::json(from);
    w["go_host_utc"] = window_from_utc_.empty() ? nlohmann::json(nullptr) : nlohmann::json(window_from_utc_);
    const std::int64_t until = window_until_ns_.load();
    w["end_host_ns"] = until == kClosed ? nlohmann::json(nullptr) : nlohmann::json(until);
    w["frames_before_go"] = before_window_.load();
    w["frames_after_end"] = after_window_.load();
    if (!streams_behind_end_.empty()) w["streams_behind_end"] = streams_behind_end_;
    sc.trial_window = std::move(w);
  }
  sc.extra = config_.extra;
  return sc;
}

}  // namespace lmc::devices
