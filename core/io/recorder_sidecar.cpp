#include "core/io/recorder_sidecar.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/io/json_checked.h"

namespace lmc {
namespace {

using nlohmann::json;

// Every key of every object of the format is spelt once, in the tables below: each entry says how
// the key is read and written, so the reader, the writer, the keys kept as unknown and
// recorder_sidecar_keys() (which the format's documentation is checked against) cannot disagree.
// A table's order is the order keys are read in, so the first bad value is the one reported.
template <class T>
struct Field {
  const char* key;
  void (*read)(const JsonReader& obj, const char* key, T& out);
  void (*write)(const T& in, const char* key, json& j);
};

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
void get(const JsonReader& obj, const char* key, bool& out) {
  if (obj.has(key)) out = obj.at(key).boolean();
}
// Raw JSON that must be an object when present (null when absent).
void get(const JsonReader& obj, const char* key, json& out) {
  if (!obj.has(key)) return;
  const JsonReader r = obj.at(key);
  r.require_object();
  out = r.json();
}

template <class M>
struct MemberOf;
template <class T, class V>
struct MemberOf<V T::*> {
  using Owner = T;
};
template <auto M>
using OwnerOf = typename MemberOf<decltype(M)>::Owner;

// A key held in one member, always written.
template <auto M>
constexpr Field<OwnerOf<M>> field(const char* key) {
  return {key, [](const JsonReader& obj, const char* k, OwnerOf<M>& out) { get(obj, k, out.*M); },
          [](const OwnerOf<M>& in, const char* k, json& j) { j[k] = in.*M; }};
}
bool is_set(const std::string& text) {
  return !text.empty();
}
bool is_set(const json& value) {
  return !value.is_null();
}
// A key held in one member, written only when set (a non-empty text, a JSON value that is not null).
template <auto M>
constexpr Field<OwnerOf<M>> field_if_set(const char* key) {
  return {key, [](const JsonReader& obj, const char* k, OwnerOf<M>& out) { get(obj, k, out.*M); },
          [](const OwnerOf<M>& in, const char* k, json& j) {
            if (is_set(in.*M)) j[k] = in.*M;
          }};
}

// An array of objects read and written through their own table.
template <class T, size_t N>
std::vector<T> read_list(const JsonReader& obj, const char* key, const Field<T> (&fields)[N]);
template <class T, size_t N>
json write_list(const std::vector<T>& list, const Field<T> (&fields)[N]);

template <class T, size_t N>
json unknown_keys(const json& j, const Field<T> (&fields)[N]) {
  json out = json::object();
  for (const auto& [key, value] : j.items()) {
    bool is_known = false;
    for (const auto& f : fields) is_known = is_known || key == f.key;
    if (!is_known) out[key] = value;
  }
  return out;
}

template <class T, size_t N>
T read_object(const JsonReader& r, const Field<T> (&fields)[N]) {
  r.require_object();
  T out;
  for (const auto& f : fields) f.read(r, f.key, out);
  out.unknown = unknown_keys(r.json(), fields);
  return out;
}

// Unknown keys first, so a known key always carries this version's value.
template <class T, size_t N>
json write_object(const T& in, const Field<T> (&fields)[N]) {
  json j = in.unknown.is_object() ? in.unknown : json::object();
  for (const auto& f : fields) f.write(in, f.key, j);
  return j;
}

template <class T, size_t N>
std::vector<T> read_list(const JsonReader& obj, const char* key, const Field<T> (&fields)[N]) {
  std::vector<T> out;
  if (!obj.has(key)) return out;
  const JsonReader list = obj.at(key);
  for (size_t i = 0; i < list.array_size(); ++i) out.push_back(read_object(list.at(i), fields));
  return out;
}

template <class T, size_t N>
json write_list(const std::vector<T>& list, const Field<T> (&fields)[N]) {
  json out = json::array();
  for (const auto& item : list) out.push_back(write_object(item, fields));
  return out;
}

template <class T, size_t N>
std::vector<std::string> keys_of(const Field<T> (&fields)[N]) {
  std::vector<std::string> out;
  for (const auto& f : fields) out.emplace_back(f.key);
  return out;
}

const Field<SidecarGap> kGapFields[] = {
    field<&SidecarGap::from_timestamp_us>("from_timestamp_us"),
    field<&SidecarGap::to_timestamp_us>("to_timestamp_us"),
    {"duration_ms",  // derived from the two times: checked, not kept
     [](const JsonReader& obj, const char* k, SidecarGap&) {
       if (obj.has(k)) obj.number(k);
     },
     [](const SidecarGap& in, const char* k, json& j) { j[k] = in.duration_ms(); }},
};

const Field<SidecarDisconnect> kDisconnectFields[] = {
    field<&SidecarDisconnect::host_time_utc>("host_time_utc"),
    field<&SidecarDisconnect::host_ns>("host_ns"),
    field<&SidecarDisconnect::message>("message"),
    field_if_set<&SidecarDisconnect::reconnected_host_time_utc>("reconnected_host_time_utc"),
    field<&SidecarDisconnect::event>("event"),
    field<&SidecarDisconnect::serial>("serial"),
    field<&SidecarDisconnect::slot>("slot"),
};

const Field<SidecarDevice> kDeviceFields[] = {
    field<&SidecarDevice::device_id>("device_id"),
    field<&SidecarDevice::slot>("slot"),
    field<&SidecarDevice::serial>("serial"),
    field<&SidecarDevice::frames_written>("frames_written"),
    field<&SidecarDevice::frames_with_hand>("frames_with_hand"),
    field<&SidecarDevice::frames_dropped_queue>("frames_dropped_queue"),
    field<&SidecarDevice::frame_id_gaps>("frame_id_gaps"),
    field<&SidecarDevice::first_timestamp_us>("first_timestamp_us"),
    field<&SidecarDevice::last_timestamp_us>("last_timestamp_us"),
    {"gaps", [](const JsonReader& obj, const char* k, SidecarDevice& out) { out.gaps = read_list(obj, k, kGapFields); },
     [](const SidecarDevice& in, const char* k, json& j) { j[k] = write_list(in.gaps, kGapFields); }},
    {"disconnects",
     [](const JsonReader& obj, const char* k, SidecarDevice& out) {
       out.disconnects = read_list(obj, k, kDisconnectFields);
     },
     [](const SidecarDevice& in, const char* k, json& j) { j[k] = write_list(in.disconnects, kDisconnectFields); }},
    field_if_set<&SidecarDevice::model>("model"),
    field_if_set<&SidecarDevice::tracking_mode>("tracking_mode"),
    field<&SidecarDevice::frames_other_side_hand>("frames_other_side_hand"),
};

const Field<SidecarViconPacket> kPacketFields[] = {
    field<&SidecarViconPacket::type>("type"),
    field<&SidecarViconPacket::packet_id>("packet_id"),
    field<&SidecarViconPacket::target>("target"),
    field<&SidecarViconPacket::datagrams_sent>("datagrams_sent"),
    field<&SidecarViconPacket::host_time_utc>("host_time_utc"),
    field<&SidecarViconPacket::host_ns>("host_ns"),
    field_if_set<&SidecarViconPacket::error>("error"),
    field_if_set<&SidecarViconPacket::warning>("warning"),
};

const Field<SidecarViconListen> kListenFields[] = {
    field<&SidecarViconListen::address>("address"),
    field<&SidecarViconListen::binding>("binding"),
    field<&SidecarViconListen::allowed_senders>("allowed_senders"),
    field<&SidecarViconListen::any_sender>("any_sender"),
    field<&SidecarViconListen::trigger_host>("trigger_host"),
    field<&SidecarViconListen::refused_datagrams>("refused_datagrams"),
    {"refused_senders",  // {address: datagrams}
     [](const JsonReader& obj, const char* k, SidecarViconListen& out) {
       if (!obj.has(k)) return;
       const JsonReader map = obj.at(k);
       map.require_object();
       for (const auto& [host, count] : map.json().items())
         out.refused_senders.emplace_back(host, int64_of(map.at(host.c_str())));
     },
     [](const SidecarViconListen& in, const char* k, json& j) {
       j[k] = json::object();
       for (const auto& [host, count] : in.refused_senders) j[k][host] = count;
     }},
    field_if_set<&SidecarViconListen::warning>("warning"),
};

// Written in one piece once the truth file exists, so no crash explains a missing file or clock:
// those two are required.
const Field<SidecarGroundTruth> kTruthFields[] = {
    {"file", [](const JsonReader& obj, const char* k, SidecarGroundTruth& out) { out.file = obj.string(k); },
     [](const SidecarGroundTruth& in, const char* k, json& j) { j[k] = in.file; }},
    {"device_clock_at_time_zero_us",
     [](const JsonReader& obj, const char* k, SidecarGroundTruth& out) {
       out.device_clock_at_time_zero_us = int64_of(obj.at(k));
     },
     [](const SidecarGroundTruth& in, const char* k, json& j) { j[k] = in.device_clock_at_time_zero_us; }},
    field<&SidecarGroundTruth::rate_hz>("rate_hz"),
    field<&SidecarGroundTruth::frames>("frames"),
    field<&SidecarGroundTruth::mapping>("mapping"),
};

constexpr const char* kFormat = "lmc-session";

const Field<RecorderSidecar> kTopFields[] = {
    {"format",
     [](const JsonReader& obj, const char* k, RecorderSidecar&) {
       if (obj.string(k) != kFormat) obj.at(k).fail("not a recorder sidecar (expected \"lmc-session\")");
     },
     [](const RecorderSidecar&, const char* k, json& j) { j[k] = kFormat; }},
    field<&RecorderSidecar::format_version>("format_version"),
    field<&RecorderSidecar::trial>("trial"),
    field<&RecorderSidecar::status>("status"),
    field_if_set<&RecorderSidecar::error>("error"),
    field_if_set<&RecorderSidecar::stopped_by>("stopped_by"),
    {"software",  // {name, version}
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       if (!obj.has(k)) return;
       const JsonReader sw = obj.at(k);
       sw.require_object();
       get(sw, "name", out.software_name);
       get(sw, "version", out.software_version);
     },
     [](const RecorderSidecar& in, const char* k, json& j) {
       j[k] = {{"name", in.software_name}, {"version", in.software_version}};
     }},
    field<&RecorderSidecar::backend>("backend"),
    field<&RecorderSidecar::recording_file>("recording_file"),
    field<&RecorderSidecar::recording_format>("recording_format"),
    field<&RecorderSidecar::host_start_utc>("host_start_utc"),
    field<&RecorderSidecar::host_stop_utc>("host_stop_utc"),
    field<&RecorderSidecar::host_start_ns>("host_start_ns"),
    field<&RecorderSidecar::host_stop_ns>("host_stop_ns"),
    field<&RecorderSidecar::layout>("layout"),
    {"serial_to_slot",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       if (!obj.has(k)) return;
       const JsonReader map = obj.at(k);
       map.require_object();
       for (const auto& [serial, slot] : map.json().items())
         out.serial_to_slot.emplace_back(serial, map.string(serial.c_str()));
     },
     [](const RecorderSidecar& in, const char* k, json& j) { j[k] = serial_to_slot_json(in.serial_to_slot); }},
    {"devices",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) { out.devices = read_list(obj, k, kDeviceFields); },
     [](const RecorderSidecar& in, const char* k, json& j) { j[k] = write_list(in.devices, kDeviceFields); }},
    field<&RecorderSidecar::frames_written>("frames_written"),
    field<&RecorderSidecar::frames_dropped>("frames_dropped"),
    {"vicon_packets",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       out.vicon_packets = read_list(obj, k, kPacketFields);
     },
     [](const RecorderSidecar& in, const char* k, json& j) { j[k] = write_list(in.vicon_packets, kPacketFields); }},
    field_if_set<&RecorderSidecar::vicon_trigger_received>("vicon_trigger_received"),
    field_if_set<&RecorderSidecar::vicon_stop_received>("vicon_stop_received"),
    field_if_set<&RecorderSidecar::vicon_alignment>("vicon_alignment"),
    {"vicon_listen",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       if (obj.has(k)) out.vicon_listen = read_object(obj.at(k), kListenFields);
     },
     [](const RecorderSidecar& in, const char* k, json& j) {
       if (in.vicon_listen) j[k] = write_object(*in.vicon_listen, kListenFields);
     }},
    field_if_set<&RecorderSidecar::trial_window>("trial_window"),
    {"events",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       if (!obj.has(k)) return;
       const JsonReader events = obj.at(k);
       events.array_size();  // must be an array
       out.events = events.json();
     },
     [](const RecorderSidecar& in, const char* k, json& j) {
       j[k] = in.events.is_array() ? in.events : json::array();
     }},
    {"ground_truth",
     [](const JsonReader& obj, const char* k, RecorderSidecar& out) {
       if (obj.has(k)) out.ground_truth = read_object(obj.at(k), kTruthFields);
     },
     [](const RecorderSidecar& in, const char* k, json& j) {
       if (in.ground_truth) j[k] = write_object(*in.ground_truth, kTruthFields);
     }},
    {"extra", [](const JsonReader& obj, const char* k, RecorderSidecar& out) { get(obj, k, out.extra); },
     [](const RecorderSidecar& in, const char* k, json& j) {
       if (in.extra.is_object() && !in.extra.empty()) j[k] = in.extra;
     }},
};

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
  return write_object(t, kTruthFields);
}

json sidecar_vicon_packet_to_json(const SidecarViconPacket& p) {
  return write_object(p, kPacketFields);
}

json sidecar_vicon_listen_to_json(const SidecarViconListen& l) {
  return write_object(l, kListenFields);
}

json recorder_sidecar_to_json(const RecorderSidecar& s) {
  return write_object(s, kTopFields);
}

std::vector<std::pair<std::string, std::vector<std::string>>> recorder_sidecar_keys() {
  return {{"", keys_of(kTopFields)},
          {"devices[]", keys_of(kDeviceFields)},
          {"gaps[]", keys_of(kGapFields)},
          {"disconnects[]", keys_of(kDisconnectFields)},
          {"vicon_packets[]", keys_of(kPacketFields)},
          {"vicon_listen", keys_of(kListenFields)},
          {"ground_truth", keys_of(kTruthFields)}};
}

SidecarViconPacket sidecar_vicon_packet_from_json(const json& j, const std::string& source) {
  return read_object(JsonReader(j, source), kPacketFields);
}

bool is_recorder_sidecar(const json& j) {
  return j.is_object() && j.contains("format") && j.at("format").is_string() &&
         j.at("format").get<std::string>() == kFormat;
}

RecorderSidecar recorder_sidecar_from_json(const json& j, const std::string& source) {
  return read_object(JsonReader(j, source), kTopFields);
}

RecorderSidecar read_recorder_sidecar(const std::filesystem::path& path) {
  const json j = read_json_file(path);
  if (!is_recorder_sidecar(j))
    throw Error(ErrorLocation(path.string(), 0, 0, "/format"),
                "not a recorder sidecar (expected \"format\": \"lmc-session\")");
  return recorder_sidecar_from_json(j, path.string());
}

}  // namespace lmc
