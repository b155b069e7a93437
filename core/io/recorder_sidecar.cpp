#include "core/io/recorder_sidecar.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/io/json_checked.h"

namespace lmc {
namespace {

using nlohmann::json;

// The keys each object of the format knows; everything else is kept in `unknown`.
constexpr const char* kTopKeys[] = {"format",
                                    "format_version",
                                    "trial",
                                    "status",
                                    "error",
                                    "stopped_by",
                                    "software",
                                    "backend",
                                    "recording_file",
                                    "recording_format",
                                    "host_start_utc",
                                    "host_stop_utc",
                                    "host_start_ns",
                                    "host_stop_ns",
                                    "layout",
                                    "serial_to_slot",
                                    "devices",
                                    "frames_written",
                                    "frames_dropped",
                                    "vicon_packets",
                                    "vicon_trigger_received",
                                    "vicon_stop_received",
                                    "vicon_alignment",
                                    "vicon_listen",
                                    "trial_window",
                                    "events",
                                    "ground_truth",
                                    "extra"};
constexpr const char* kDeviceKeys[] = {"device_id",
                                       "slot",
                                       "serial",
                                       "frames_written",
                                       "frames_with_hand",
                                       "frames_dropped_queue",
                                       "frame_id_gaps",
                                       "first_timestamp_us",
                                       "last_timestamp_us",
                                       "gaps",
                                       "disconnects",
                                       "model",
                                       "tracking_mode",
                                       "frames_other_side_hand"};
constexpr const char* kGapKeys[] = {"from_timestamp_us", "to_timestamp_us", "duration_ms"};
constexpr const char* kDisconnectKeys[] = {"host_time_utc", "host_ns", "message", "reconnected_host_time_utc",
                                           "event",         "serial",  "slot"};
constexpr const char* kPacketKeys[] = {"type",          "packet_id", "target", "datagrams_sent",
                                       "host_time_utc", "host_ns",   "error",  "warning"};
constexpr const char* kListenKeys[] = {"address",      "binding",           "allowed_senders", "any_sender",
                                       "trigger_host", "refused_datagrams", "refused_senders", "warning"};
constexpr const char* kTruthKeys[] = {"file", "rate_hz", "frames", "device_clock_at_time_zero_us", "mapping"};

template <size_t N>
json unknown_keys(const json& j, const char* const (&known)[N]) {
  json out = json::object();
  for (const auto& [key, value] : j.items()) {
    bool is_known = false;
    for (const char* k : known) is_known = is_known || key == k;
    if (!is_known) out[key] = value;
  }
  return out;
}

// Unknown keys first, so a known key always carries this version's value.
json with_unknown(const json& unknown) {
  return unknown.is_object() ? unknown : json::object();
}

std::int64_t int64_of(const JsonReader& r) {
  if (!r.json().is_number_integer()) r.fail("expected an integer");
  if (r.json().is_number_unsigned() &&
      r.json().get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    r.fail("integer out of range");
  return r.json().get<std::int64_t>();
}

// Absent (or null) keys keep the default: lenient for what a crash leaves out, strict for what
// is there.
void get(const JsonReader& obj, const char* key, std::string& out) {
  if (obj.has(key)) out = obj.string(key);
}
void get(const JsonReader& obj, const char* key, std::int64_t& out) {
  if (obj.has(key)) out = int64_of(obj.at(key));
}
void get(const JsonReader& obj, const char* key, int& out) {
  if (obj.has(key)) out = obj.at(key).integer();
}
void get(const JsonReader& obj, const char* key, double& out) {
  if (obj.has(key)) out = obj.number(key);
}
// Raw JSON that must be an object when present (null when absent).
void get_object(const JsonReader& obj, const char* key, json& out) {
  if (!obj.has(key)) return;
  const JsonReader r = obj.at(key);
  r.require_object();
  out = r.json();
}

SidecarGap gap_from(const JsonReader& r) {
  r.require_object();
  SidecarGap g;
  get(r, "from_timestamp_us", g.from_timestamp_us);
  get(r, "to_timestamp_us", g.to_timestamp_us);
  if (r.has("duration_ms")) r.number("duration_ms");  // derived; checked, not kept
  g.unknown = unknown_keys(r.json(), kGapKeys);
  return g;
}

SidecarDisconnect disconnect_from(const JsonReader& r) {
  r.require_object();
  SidecarDisconnect d;
  get(r, "host_time_utc", d.host_time_utc);
  get(r, "host_ns", d.host_ns);
  get(r, "message", d.message);
  get(r, "reconnected_host_time_utc", d.reconnected_host_time_utc);
  get(r, "event", d.event);
  get(r, "serial", d.serial);
  get(r, "slot", d.slot);
  d.unknown = unknown_keys(r.json(), kDisconnectKeys);
  return d;
}

SidecarDevice device_from(const JsonReader& r) {
  r.require_object();
  SidecarDevice d;
  get(r, "device_id", d.device_id);
  get(r, "slot", d.slot);
  get(r, "serial", d.serial);
  get(r, "frames_written", d.frames_written);
  get(r, "frames_with_hand", d.frames_with_hand);
  get(r, "frames_dropped_queue", d.frames_dropped_queue);
  get(r, "frame_id_gaps", d.frame_id_gaps);
  get(r, "first_timestamp_us", d.first_timestamp_us);
  get(r, "last_timestamp_us", d.last_timestamp_us);
  if (r.has("gaps")) {
    const JsonReader gaps = r.at("gaps");
    for (size_t i = 0; i < gaps.array_size(); ++i) d.gaps.push_back(gap_from(gaps.at(i)));
  }
  if (r.has("disconnects")) {
    const JsonReader list = r.at("disconnects");
    for (size_t i = 0; i < list.array_size(); ++i) d.disconnects.push_back(disconnect_from(list.at(i)));
  }
  get(r, "model", d.model);
  get(r, "tracking_mode", d.tracking_mode);
  get(r, "frames_other_side_hand", d.frames_other_side_hand);
  d.unknown = unknown_keys(r.json(), kDeviceKeys);
  return d;
}

SidecarViconPacket packet_from(const JsonReader& r) {
  r.require_object();
  SidecarViconPacket p;
  get(r, "type", p.type);
  get(r, "packet_id", p.packet_id);
  get(r, "target", p.target);
  get(r, "datagrams_sent", p.datagrams_sent);
  get(r, "host_time_utc", p.host_time_utc);
  get(r, "host_ns", p.host_ns);
  get(r, "error", p.error);
  get(r, "warning", p.warning);
  p.unknown = unknown_keys(r.json(), kPacketKeys);
  return p;
}

SidecarViconListen listen_from(const JsonReader& r) {
  r.require_object();
  SidecarViconListen l;
  get(r, "address", l.address);
  get(r, "binding", l.binding);
  get(r, "allowed_senders", l.allowed_senders);
  if (r.has("any_sender")) l.any_sender = r.at("any_sender").boolean();
  get(r, "trigger_host", l.trigger_host);
  get(r, "refused_datagrams", l.refused_datagrams);
  if (r.has("refused_senders")) {
    const JsonReader map = r.at("refused_senders");
    map.require_object();
    for (const auto& [host, count] : map.json().items())
      l.refused_senders.emplace_back(host, int64_of(map.at(host.c_str())));
  }
  get(r, "warning", l.warning);
  l.unknown = unknown_keys(r.json(), kListenKeys);
  return l;
}

// Written in one piece once the truth file exists, so no crash explains a missing file or clock:
// those two are required.
SidecarGroundTruth truth_from(const JsonReader& r) {
  r.require_object();
  SidecarGroundTruth t;
  t.file = r.string("file");
  t.device_clock_at_time_zero_us = int64_of(r.at("device_clock_at_time_zero_us"));
  get(r, "rate_hz", t.rate_hz);
  get(r, "frames", t.frames);
  get(r, "mapping", t.mapping);
  t.unknown = unknown_keys(r.json(), kTruthKeys);
  return t;
}

json gap_to_json(const SidecarGap& g) {
  json j = with_unknown(g.unknown);
  j["from_timestamp_us"] = g.from_timestamp_us;
  j["to_timestamp_us"] = g.to_timestamp_us;
  j["duration_ms"] = g.duration_ms();
  return j;
}

json disconnect_to_json(const SidecarDisconnect& d) {
  json j = with_unknown(d.unknown);
  j["host_time_utc"] = d.host_time_utc;
  j["host_ns"] = d.host_ns;
  j["message"] = d.message;
  j["event"] = d.event;
  j["serial"] = d.serial;
  j["slot"] = d.slot;
  if (!d.reconnected_host_time_utc.empty()) j["reconnected_host_time_utc"] = d.reconnected_host_time_utc;
  return j;
}

json sidecar_device_to_json(const SidecarDevice& d) {
  json j = with_unknown(d.unknown);
  j["device_id"] = d.device_id;
  j["slot"] = d.slot;
  j["serial"] = d.serial;
  j["frames_written"] = d.frames_written;
  j["frames_with_hand"] = d.frames_with_hand;
  j["frames_dropped_queue"] = d.frames_dropped_queue;
  j["frame_id_gaps"] = d.frame_id_gaps;
  j["first_timestamp_us"] = d.first_timestamp_us;
  j["last_timestamp_us"] = d.last_timestamp_us;
  j["gaps"] = json::array();
  for (const auto& g : d.gaps) j["gaps"].push_back(gap_to_json(g));
  j["disconnects"] = json::array();
  for (const auto& x : d.disconnects) j["disconnects"].push_back(disconnect_to_json(x));
  if (!d.model.empty()) j["model"] = d.model;
  if (!d.tracking_mode.empty()) j["tracking_mode"] = d.tracking_mode;
  j["frames_other_side_hand"] = d.frames_other_side_hand;
  return j;
}

}  // namespace

double RecorderSidecar::host_duration_s() const {
  if (host_start_ns <= 0 || host_stop_ns <= host_start_ns) return std::nan("");
  return static_cast<double>(host_stop_ns - host_start_ns) * 1e-9;
}

const SidecarDevice* RecorderSidecar::device(int device_id) const {
  for (const auto& d : devices)
    if (d.device_id == device_id) return &d;
  return nullptr;
}

json serial_to_slot_json(const std::vector<std::pair<std::string, std::string>>& map) {
  json j = json::object();
  for (const auto& [serial, slot] : map) j[serial] = slot;
  return j;
}

json sidecar_ground_truth_to_json(const SidecarGroundTruth& t) {
  json j = with_unknown(t.unknown);
  j["file"] = t.file;
  j["rate_hz"] = t.rate_hz;
  j["frames"] = t.frames;
  j["device_clock_at_time_zero_us"] = t.device_clock_at_time_zero_us;
  j["mapping"] = t.mapping;
  return j;
}

json sidecar_vicon_packet_to_json(const SidecarViconPacket& p) {
  json j = with_unknown(p.unknown);
  j["type"] = p.type;
  j["packet_id"] = p.packet_id;
  j["target"] = p.target;
  j["datagrams_sent"] = p.datagrams_sent;
  j["host_time_utc"] = p.host_time_utc;
  j["host_ns"] = p.host_ns;
  if (!p.error.empty()) j["error"] = p.error;
  if (!p.warning.empty()) j["warning"] = p.warning;
  return j;
}

json sidecar_vicon_listen_to_json(const SidecarViconListen& l) {
  json j = with_unknown(l.unknown);
  j["address"] = l.address;
  j["binding"] = l.binding;
  j["allowed_senders"] = l.allowed_senders;
  j["any_sender"] = l.any_sender;
  j["trigger_host"] = l.trigger_host;
  j["refused_datagrams"] = l.refused_datagrams;
  j["refused_senders"] = json::object();
  for (const auto& [host, count] : l.refused_senders) j["refused_senders"][host] = count;
  if (!l.warning.empty()) j["warning"] = l.warning;
  return j;
}

json recorder_sidecar_to_json(const RecorderSidecar& s) {
  json j = with_unknown(s.unknown);
  j["format"] = "lmc-session";
  j["format_version"] = s.format_version;
  j["trial"] = s.trial;
  j["status"] = s.status;
  if (!s.error.empty()) j["error"] = s.error;
  if (!s.stopped_by.empty()) j["stopped_by"] = s.stopped_by;
  j["software"] = {{"name", s.software_name}, {"version", s.software_version}};
  j["backend"] = s.backend;
  j["recording_file"] = s.recording_file;
  j["recording_format"] = s.recording_format;
  j["host_start_utc"] = s.host_start_utc;
  j["host_stop_utc"] = s.host_stop_utc;
  j["host_start_ns"] = s.host_start_ns;
  j["host_stop_ns"] = s.host_stop_ns;
  j["layout"] = s.layout;
  j["serial_to_slot"] = serial_to_slot_json(s.serial_to_slot);
  j["devices"] = json::array();
  for (const auto& d : s.devices) j["devices"].push_back(sidecar_device_to_json(d));
  j["frames_written"] = s.frames_written;
  j["frames_dropped"] = s.frames_dropped;
  j["vicon_packets"] = json::array();
  for (const auto& p : s.vicon_packets) j["vicon_packets"].push_back(sidecar_vicon_packet_to_json(p));
  if (!s.vicon_trigger_received.is_null()) j["vicon_trigger_received"] = s.vicon_trigger_received;
  if (!s.vicon_stop_received.is_null()) j["vicon_stop_received"] = s.vicon_stop_received;
  if (!s.vicon_alignment.is_null()) j["vicon_alignment"] = s.vicon_alignment;
  if (s.vicon_listen) j["vicon_listen"] = sidecar_vicon_listen_to_json(*s.vicon_listen);
  if (!s.trial_window.is_null()) j["trial_window"] = s.trial_window;
  j["events"] = s.events.is_array() ? s.events : json::array();
  if (s.ground_truth) j["ground_truth"] = sidecar_ground_truth_to_json(*s.ground_truth);
  if (s.extra.is_object() && !s.extra.empty()) j["extra"] = s.extra;
  return j;
}

SidecarViconPacket sidecar_vicon_packet_from_json(const json& j, const std::string& source) {
  return packet_from(JsonReader(j, source));
}

bool is_recorder_sidecar(const json& j) {
  return j.is_object() && j.contains("format") && j.at("format").is_string() &&
         j.at("format").get<std::string>() == "lmc-session";
}

RecorderSidecar recorder_sidecar_from_json(const json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.require_object();
  if (r.string("format") != "lmc-session") r.at("format").fail("not a recorder sidecar (expected \"lmc-session\")");
  RecorderSidecar s;
  get(r, "format_version", s.format_version);
  get(r, "trial", s.trial);
  get(r, "status", s.status);
  get(r, "error", s.error);
  get(r, "stopped_by", s.stopped_by);
  if (r.has("software")) {
    const JsonReader sw = r.at("software");
    sw.require_object();
    get(sw, "name", s.software_name);
    get(sw, "version", s.software_version);
  }
  get(r, "backend", s.backend);
  get(r, "recording_file", s.recording_file);
  get(r, "recording_format", s.recording_format);
  get(r, "host_start_utc", s.host_start_utc);
  get(r, "host_stop_utc", s.host_stop_utc);
  get(r, "host_start_ns", s.host_start_ns);
  get(r, "host_stop_ns", s.host_stop_ns);
  get_object(r, "layout", s.layout);
  if (r.has("serial_to_slot")) {
    const JsonReader map = r.at("serial_to_slot");
    map.require_object();
    for (const auto& [serial, slot] : map.json().items())
      s.serial_to_slot.emplace_back(serial, map.string(serial.c_str()));
  }
  if (r.has("devices")) {
    const JsonReader list = r.at("devices");
    for (size_t i = 0; i < list.array_size(); ++i) s.devices.push_back(device_from(list.at(i)));
  }
  get(r, "frames_written", s.frames_written);
  get(r, "frames_dropped", s.frames_dropped);
  if (r.has("vicon_packets")) {
    const JsonReader list = r.at("vicon_packets");
    for (size_t i = 0; i < list.array_size(); ++i) s.vicon_packets.push_back(packet_from(list.at(i)));
  }
  get_object(r, "vicon_trigger_received", s.vicon_trigger_received);
  get_object(r, "vicon_stop_received", s.vicon_stop_received);
  get_object(r, "vicon_alignment", s.vicon_alignment);
  if (r.has("vicon_listen")) s.vicon_listen = listen_from(r.at("vicon_listen"));
  get_object(r, "trial_window", s.trial_window);
  if (r.has("events")) {
    const JsonReader events = r.at("events");
    events.array_size();  // must be an array
    s.events = events.json();
  }
  if (r.has("ground_truth")) s.ground_truth = truth_from(r.at("ground_truth"));
  get_object(r, "extra", s.extra);
  s.unknown = unknown_keys(j, kTopKeys);
  return s;
}

RecorderSidecar read_recorder_sidecar(const std::filesystem::path& path) {
  const json j = read_json_file(path);
  if (!is_recorder_sidecar(j))
    throw Error(ErrorLocation(path.string(), 0, 0, "/format"),
                "not a recorder sidecar (expected \"format\": \"lmc-session\")");
  return recorder_sidecar_from_json(j, path.string());
}

}  // namespace lmc
