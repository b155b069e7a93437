#pragma once
// The recorder's sidecar `LMC_<trial>.session.json` as one type (sessions/README.md has the key
// table). The recorder writes it with recorder_sidecar_to_json, and `lmc info`, processing, the
// quality check and the session runner read it with read_recorder_sidecar, so the format has one
// reader and one writer, and each key is spelt once, in recorder_sidecar.cpp's tables. Reading is
// lenient where a crash explains a gap (a sidecar left at "recording" lacks the stop time and the
// final counts: those stay at their defaults and `complete` is false) and strict where a value is
// present but wrong (a string where a number belongs is an error naming the file and the JSON path).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace lmc {

struct SidecarGap {
  std::int64_t from_timestamp_us = 0;  // last frame before the silence (device clock)
  std::int64_t to_timestamp_us = 0;    // first frame after it
  double duration_ms() const { return static_cast<double>(to_timestamp_us - from_timestamp_us) / 1000.0; }
  nlohmann::json unknown = nlohmann::json::object();  // keys this version does not know (kept on rewrite)
};

struct SidecarDisconnect {
  std::string host_time_utc;
  std::int64_t host_ns = 0;
  std::string message;
  std::string reconnected_host_time_utc;  // empty when it never came back during the trial
  // The device event that was the disconnect ("lost"), and whose it was.
  std::string event, serial, slot;
  nlohmann::json unknown = nlohmann::json::object();
};

struct SidecarDevice {
  int device_id = 0;  // slot number, LMC1 = 1
  std::string slot;
  std::string serial;
  std::int64_t frames_written = 0;
  std::int64_t frames_with_hand = 0;
  std::int64_t frames_dropped_queue = 0;
  std::int64_t frame_id_gaps = 0;
  std::int64_t first_timestamp_us = 0;
  std::int64_t last_timestamp_us = 0;
  std::vector<SidecarGap> gaps;
  std::vector<SidecarDisconnect> disconnects;
  // What the controller is and how it tracked (optional: empty / 0 in files written before they
  // were kept, and from backends that do not know): its model, its tracking mode at the end of the
  // trial, and the frames whose only hand was classified as the other side and kept.
  std::string model;
  std::string tracking_mode;
  std::int64_t frames_other_side_hand = 0;
  nlohmann::json unknown = nlohmann::json::object();
};

struct SidecarViconPacket {
  std::string type;  // CaptureStart | CaptureStop
  std::int64_t packet_id = 0;
  std::string target;
  int datagrams_sent = 0;
  std::string host_time_utc;
  std::int64_t host_ns = 0;
  std::string error;    // sending failed
  std::string warning;  // e.g. the PacketID state file could not be used
  nlohmann::json unknown = nlohmann::json::object();
};

// Listen mode: where CaptureStart was awaited, whom it was taken from and what was refused. Absent
// (nullopt) in sidecars of trials that did not listen, and in files written before it existed.
struct SidecarViconListen {
  std::string address;          // where the listener listened ("0.0.0.0:30 on eth0")
  std::string binding;          // how that was chosen
  std::string allowed_senders;  // the allowed senders as configured, resolved; "" = any sender
  bool any_sender = false;
  std::string trigger_host;            // the sender of the CaptureStart that began the trial (IPv4 address)
  std::int64_t refused_datagrams = 0;  // from senders that are not allowed
  std::vector<std::pair<std::string, std::int64_t>> refused_senders;  // sender address → datagrams
  std::string warning;                                                // e.g. any sender was obeyed
  nlohmann::json unknown = nlohmann::json::object();
};

struct SidecarGroundTruth {
  std::string file;  // T.trc beside the sidecar
  double rate_hz = 0;
  std::int64_t frames = 0;
  std::int64_t device_clock_at_time_zero_us = 0;
  std::string mapping;
  nlohmann::json unknown = nlohmann::json::object();
};

struct RecorderSidecar {
  int format_version = 1;
  std::string trial;
  std::string status;  // recording | completed | failed | aborted
  std::string error;
  std::string stopped_by;
  std::string software_name, software_version;
  std::string backend;  // sim | leapc | replay
  std::string recording_file, recording_format;
  std::string host_start_utc, host_stop_utc;
  std::int64_t host_start_ns = 0, host_stop_ns = 0;
  nlohmann::json layout;  // the full layout JSON (core/io/layout_json.h reads it)
  std::vector<std::pair<std::string, std::string>> serial_to_slot;
  std::vector<SidecarDevice> devices;
  std::int64_t frames_written = 0, frames_dropped = 0;
  std::vector<SidecarViconPacket> vicon_packets;
  nlohmann::json vicon_trigger_received;  // null unless listen mode
  nlohmann::json vicon_stop_received;
  nlohmann::json vicon_alignment;  // null when no CaptureStart (devices/record/clock_alignment.h)
  std::optional<SidecarViconListen> vicon_listen;
  // When the subject was told to go and what of the stream lay outside the trial (null in files
  // written before the window was recorded, which hold every row from the recorder's start).
  nlohmann::json trial_window;
  nlohmann::json events = nlohmann::json::array();
  std::optional<SidecarGroundTruth> ground_truth;
  nlohmann::json extra = nlohmann::json::object();
  // Keys this version does not know, kept so a rewrite never drops what a newer writer added.
  nlohmann::json unknown = nlohmann::json::object();

  bool complete() const { return status != "recording"; }
  double host_duration_s() const;  // NaN unless both host times are known and ordered
  const SidecarDevice* device(int device_id) const;
};

// Serial → slot as the sidecar writes it ({serial: slot}).
nlohmann::json serial_to_slot_json(const std::vector<std::pair<std::string, std::string>>& map);
nlohmann::json sidecar_ground_truth_to_json(const SidecarGroundTruth& truth);
nlohmann::json sidecar_vicon_packet_to_json(const SidecarViconPacket& packet);
nlohmann::json sidecar_vicon_listen_to_json(const SidecarViconListen& listen);
// One packet as the recorder's callers describe it (keys as in vicon_packets[]); `source` names it in errors.
SidecarViconPacket sidecar_vicon_packet_from_json(const nlohmann::json& j, const std::string& source);

// The JSON of the sidecar (keys as sessions/README.md lists them). Optional keys (error,
// stopped_by, the Vicon notes, ground_truth, extra) are written only when set.
nlohmann::json recorder_sidecar_to_json(const RecorderSidecar& sidecar);
// `source` names the file in errors ("…/LMC_T.session.json#/devices/2/frames_written: …").
RecorderSidecar recorder_sidecar_from_json(const nlohmann::json& j, const std::string& source);
// Reads the file (limits and errors as read_json_file) and checks "format": "lmc-session".
RecorderSidecar read_recorder_sidecar(const std::filesystem::path& path);
// True when the JSON says it is a sidecar ("format": "lmc-session").
bool is_recorder_sidecar(const nlohmann::json& j);
// Every key the format knows, per object: "" (the top level), "devices[]", "gaps[]",
// "disconnects[]", "vicon_packets[]", "vicon_listen" and "ground_truth". The reader and the writer
// use the same table; a test checks that sessions/README.md describes each key.
std::vector<std::pair<std::string, std::vector<std::string>>> recorder_sidecar_keys();

}  // namespace lmc
