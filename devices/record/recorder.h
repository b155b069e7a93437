#pragma once
// The trial recorder: every frame of every device goes to one file in the study's raw
// format (core/io/lmc_recording.h, so existing tools read it) plus a JSON sidecar describing the
// session (sessions/README.md). Frames arrive from several device threads; they take turns
// (producer_mutex_) to push into a bounded single-producer/single-consumer ring, so the ring sees
// one producer at a time and the writer never takes a producer's lock (docs/architecture.md). A
// writer thread of its own (a std::jthread, stopped through its stop token) sleeps on a condition
// variable until frames arrive, formats and writes them, and pushes its buffer to the file at
// least once a second, so a crash loses at most the last second and leaves a readable file. A
// write error (disk full) stops the recording with a clear message and keeps everything written
// before it; so does an exception in the writer, which ends the recording as failed instead of
// terminating the program.
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "core/io/recorder_sidecar.h"
#include "core/layout/layout.h"
#include "core/session/trial_files.h"
#include "devices/frame_consumer.h"
#include "devices/record/byte_sink.h"
#include "devices/spsc_queue.h"

namespace lmc::devices {

struct RecorderConfig {
  std::filesystem::path output_dir;
  std::string trial;  // checked with validate_trial_name
  Layout layout;
  std::string backend;
  size_t queue_capacity = 8192;             // frames (≈17 s of four devices at 120 Hz)
  std::int64_t flush_interval_ms = 250;     // buffer → file at least this often (≤ 1000)
  std::int64_t gap_threshold_us = 250'000;  // a device silent this long is a gap in the sidecar
  // Tests inject failing sinks; default opens the file.
  std::function<std::unique_ptr<ByteSink>(const std::filesystem::path&)> open_sink;
  nlohmann::json extra = nlohmann::json::object();  // e.g. the simulator's config and motion
  // The file holds the trial only: no row is written until open_window() says when the subject
  // was told to go (the countdown before it is not part of the trial). Off: every row from start().
  bool wait_for_go = false;
  nlohmann::json trial_window =
      nlohmann::json::object();  // more of the sidecar's trial_window (countdown_s, planned_s)
};

// The trial's three files (core/session/trial_files.h, where the naming rule lives), once `trial`
// has passed the trial-name rule: a name from outside becomes a file name only through here.
TrialFiles checked_trial_files(const std::filesystem::path& dir, const std::string& trial);

struct GapRecord {
  std::int64_t from_timestamp_us = 0;  // last frame before the gap (device clock)
  std::int64_t to_timestamp_us = 0;    // first frame after it
};

struct DeviceRecordStats {
  int device_id = 0;
  std::string slot;
  std::string serial;
  std::int64_t frames_written = 0;
  std::int64_t frames_with_hand = 0;
  std::int64_t frames_dropped_queue = 0;  // offered while the queue was full
  std::int64_t frame_id_gaps = 0;         // frames missing according to the device counter
  std::int64_t first_timestamp_us = 0;
  std::int64_t last_timestamp_us = 0;
  std::vector<GapRecord> gaps;
  std::vector<nlohmann::json> disconnects;  // {host_time_utc, host_ns, message, reconnected}
  // From the backend's device events and other_side_hand() (sidecar keys of the same names).
  std::string model;
  std::string tracking_mode;
  std::int64_t frames_other_side_hand = 0;
};

// kFailed: a write error stopped the recording; kAborted: the caller stopped the trial because
// of an error elsewhere (Vicon refused the trigger, a device never streamed, …). Both keep every
// row written and put the reason in `error` and in the sidecar.
enum class RecorderState { kIdle, kRecording, kStopped, kFailed, kAborted };

struct RecorderStatus {
  RecorderState state = RecorderState::kIdle;
  std::string error;  // set when kFailed or kAborted
  std::int64_t frames_written = 0;
  std::int64_t frames_dropped = 0;
  size_t queue_depth = 0;
  std::map<int, DeviceRecordStats> devices;  // by device id
};

class Recorder final : public FrameConsumer {
 public:
  explicit Recorder(RecorderConfig config);
  ~Recorder() override;
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // Creates the files (header + sidecar with status "recording") and starts the writer thread.
  // Throws lmc::Error for a bad trial name or an uncreatable file.
  void start();
  // Drains the queue, writes, syncs and closes the file, writes the final sidecar atomically.
  // `serial_to_slot` is the hub's final map. A non-empty `abort_reason` says the trial ended
  // because of an error outside the recorder: the sidecar then says status "aborted" with that
  // text as `error` (a write error of the recorder's own stays "failed"). Returns the final
  // status (kStopped, kFailed or kAborted).
  RecorderStatus stop(const std::vector<std::pair<std::string, std::string>>& serial_to_slot = {},
                      const std::string& abort_reason = {});

  RecorderStatus status() const;
  bool failed() const { return failed_.load(); }
  const TrialFiles& paths() const { return paths_; }

  // Records a Vicon trigger packet in the sidecar (any thread). The JSON form takes the keys of
  // the sidecar's vicon_packets[] and throws lmc::Error for a mistyped one.
  void note_vicon_packet(SidecarViconPacket packet);
  void note_vicon_packet(const nlohmann::json& packet);
  // What ended the trial early (sidecar "stopped_by"; any thread, before stop).
  void note_stopped_by(std::string what);
  // Listen mode: where Vicon was awaited, who triggered, what was refused (sidecar
  // "vicon_listen"; any thread, before stop; a later call replaces an earlier one).
  void note_vicon_listen(SidecarViconListen listen);
  // The simulator's truth file (sidecar "ground_truth"; before stop).
  void note_ground_truth(SidecarGroundTruth truth);
  // A JSON-valued key of the sidecar: vicon_alignment, vicon_trigger_received,
  // vicon_stop_received; any other key is kept beside them as a key this format does not know.
  void note(const std::string& key, nlohmann::json value);

  // The trial's window on the host clock (wait_for_go): rows received in [from_ns, until_ns) are
  // written; the others are counted as outside the trial, never as lost. Any thread, once; until
  // takes effect before from, so no row sees an open window without its end.
  void open_window(std::int64_t from_ns, std::int64_t until_ns = std::numeric_limits<std::int64_t>::max());
  std::string window_from_utc() const;  // when open_window() was called ("" before)
  // The window's end on the host clock; int64 max while it has none.
  std::int64_t window_until_ns() const { return window_until_ns_.load(); }
  // The devices (by device id) that have offered frames but none received at or after
  // `host_ns`: a frame of theirs stamped before it may still be on its way.
  std::vector<int> devices_behind(std::int64_t host_ns) const;
  // Slots whose stream had not passed the window's end when the trial closed (sidecar
  // trial_window.streams_behind_end; before stop).
  void note_streams_behind_end(std::vector<std::string> slots);

  // FrameConsumer (device threads).
  bool offer(const HandFrame& frame, std::int64_t host_receive_ns, bool may_wait) override;
  void device_event(const DeviceEvent& event, int device_id, const std::string& slot) override;
  void other_side_hand(int device_id, std::int64_t host_receive_ns) override;

 private:
  // A frame on its way to the writer, with the host time it arrived.
  struct QueuedFrame {
    HandFrame frame;
    std::int64_t host_receive_ns = 0;
  };
  // The writer thread's entry: run() with every exception caught and reported as the failure.
  void writer_main(std::stop_token stop) noexcept;
  void run(const std::stop_token& stop);
  // Wakes the writer after a push (any producer, producer_mutex_ held).
  void wake_writer();
  // A formatted row waiting in the write buffer; its statistics count once it reached the file.
  struct PendingRow {
    int device_id = 0;
    std::int64_t frame_id = 0;
    std::int64_t timestamp_us = 0;
    bool hand_present = false;
    size_t end = 0;  // offset just past the row's newline in the buffer
  };
  void write_queued_frame(const QueuedFrame& queued, std::string& buffer, std::vector<PendingRow>& pending);
  void count_row(const PendingRow& row);  // stats_mutex_ held
  bool push_buffer(std::string& buffer, std::vector<PendingRow>& pending);
  void fail(const std::string& message);
  RecorderSidecar sidecar(const char* state) const;  // stats_mutex_ not held

  static constexpr std::int64_t kClosed = std::numeric_limits<std::int64_t>::max();
  RecorderConfig config_;
  TrialFiles paths_;
  std::atomic<std::int64_t> window_from_ns_{kClosed};
  std::atomic<std::int64_t> window_until_ns_{kClosed};
  std::atomic<std::int64_t> before_window_{0}, after_window_{0};
  // The latest host_receive_ns offered per device id (1…kTrackedDevices; int64 min: none yet).
  static constexpr int kTrackedDevices = 64;
  std::array<std::atomic<std::int64_t>, kTrackedDevices + 1> latest_offered_ns_;
  std::vector<std::string> streams_behind_end_;  // stats_mutex_
  // The latest frames offered before the window opened (producer_mutex_).
  static constexpr size_t kHeldBeforeGo = 2048;
  std::deque<QueuedFrame> held_before_go_;
  std::string window_from_utc_;  // stats_mutex_
  std::unique_ptr<ByteSink> sink_;
  SpscQueue<QueuedFrame> queue_;
  // Serialises producers (several device threads), so the ring has one producer at a time; never
  // taken by the writer.
  std::mutex producer_mutex_;
  // A producer that may wait for room sleeps on room_ (under producer_mutex_) while the ring is
  // full; the writer notifies it as it takes frames.
  std::condition_variable room_;
  std::atomic<int> producers_waiting_{0};
  // The writer sleeps on wake_ (under wake_mutex_) while the ring is empty, until a push, its
  // flush deadline or a stop request.
  std::mutex wake_mutex_;
  std::condition_variable wake_;  // no stop-token waits: run() says why
  mutable std::mutex stats_mutex_;
  std::map<int, DeviceRecordStats> stats_;
  std::map<int, std::int64_t> last_frame_id_;
  std::vector<SidecarViconPacket> vicon_packets_;
  std::vector<nlohmann::json> events_;
  nlohmann::json notes_ = nlohmann::json::object();
  std::string stopped_by_;
  std::optional<SidecarGroundTruth> ground_truth_;
  std::optional<SidecarViconListen> vicon_listen_;
  std::vector<std::pair<std::string, std::string>> serial_to_slot_;
  std::string host_start_utc_, host_stop_utc_;
  std::int64_t host_start_ns_ = 0, host_stop_ns_ = 0;
  std::string error_;
  std::atomic<bool> failed_{false};
  std::atomic<bool> aborted_{false};
  std::atomic<bool> stop_requested_{false};  // no frame of the trial is accepted any more
  std::atomic<bool> started_{false};
  std::atomic<std::int64_t> dropped_{0};
  std::atomic<std::int64_t> written_{0};
  std::jthread thread_;  // last: stopped and joined before anything it uses is destroyed
};

const char* recorder_state_name(RecorderState s);

}  // namespace lmc::devices
