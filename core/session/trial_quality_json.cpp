// The quality report as JSON (trial_quality.h): the session journal and the manifest keep it, so
// a reviewer sees the verdict a trial got when it was recorded. Unknown numbers (a range of
// motion never measured, a finger never in view because the hand never was) are written as null.
#include <cmath>
#include <limits>

#include "core/io/json_checked.h"
#include "core/session/trial_quality.h"

namespace lmc {

namespace {

using nlohmann::json;

json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

double number_or_nan(const JsonReader& r, const char* key) {
  return r.has(key) ? r.number(key) : std::numeric_limits<double>::quiet_NaN();
}

// Counts are 64-bit (frames of a long trial); JsonReader::integer stops at int.
std::int64_t count(const JsonReader& r, const char* key) {
  const JsonReader v = r.at(key);
  if (!v.json().is_number_integer()) v.fail("expected an integer");
  return v.json().get<std::int64_t>();
}

json quality_device_to_json(const DeviceQuality& d) {
  return json{{"device_id", d.device_id},
              {"slot", d.slot},
              {"serial", d.serial},
              {"frames", d.frames},
              {"median_rate_hz", d.median_rate_hz},
              {"rate_p5_hz", d.rate_p5_hz},
              {"rate_p95_hz", d.rate_p95_hz},
              {"hand_fraction", d.hand_fraction},
              {"longest_gap_s", d.longest_gap_s},
              {"longest_no_hand_s", d.longest_no_hand_s},
              {"frame_id_gaps", d.frame_id_gaps},
              {"dropped", d.dropped},
              {"disconnects", d.disconnects},
              {"other_side_hand_frames", d.other_side_hand_frames}};
}

DeviceQuality device_from_json(const JsonReader& r) {
  r.only_keys({"device_id", "slot", "serial", "frames", "median_rate_hz", "rate_p5_hz", "rate_p95_hz", "hand_fraction",
               "longest_gap_s", "longest_no_hand_s", "frame_id_gaps", "dropped", "disconnects",
               "other_side_hand_frames"});
  DeviceQuality d;
  d.device_id = r.at("device_id").integer();
  d.slot = r.string("slot");
  d.serial = r.string_or("serial", "");
  d.frames = count(r, "frames");
  d.median_rate_hz = r.number("median_rate_hz");
  d.rate_p5_hz = r.number("rate_p5_hz");
  d.rate_p95_hz = r.number("rate_p95_hz");
  d.hand_fraction = r.number("hand_fraction");
  d.longest_gap_s = r.number("longest_gap_s");
  d.longest_no_hand_s = r.number("longest_no_hand_s");
  d.frame_id_gaps = count(r, "frame_id_gaps");
  d.dropped = count(r, "dropped");
  d.disconnects = r.at("disconnects").integer();
  // Optional: reports written before the count was kept have none.
  if (r.has("other_side_hand_frames")) d.other_side_hand_frames = count(r, "other_side_hand_frames");
  return d;
}

json vicon_to_json(const ViconQuality& v) {
  json j{{"expected", v.expected},
         {"start_sent", v.start_sent},
         {"stop_sent", v.stop_sent},
         {"error", v.error},
         {"export_found", v.export_found ? json(*v.export_found) : json(nullptr)},
         {"export_file", v.export_file}};
  // Only in listen mode, so a verdict of a trial that did not listen reads as it always did.
  if (v.listened) {
    j["listened"] = true;
    j["trigger_host"] = v.trigger_host;
    j["any_sender"] = v.any_sender;
    j["refused_datagrams"] = v.refused_datagrams;
    j["refused_hosts"] = v.refused_hosts;
  }
  return j;
}

ViconQuality vicon_from_json(const JsonReader& r) {
  r.only_keys({"expected", "start_sent", "stop_sent", "error", "export_found", "export_file", "listened",
               "trigger_host", "any_sender", "refused_datagrams", "refused_hosts"});
  ViconQuality v;
  v.expected = r.at("expected").boolean();
  v.start_sent = r.at("start_sent").boolean();
  v.stop_sent = r.at("stop_sent").boolean();
  v.error = r.string_or("error", "");
  if (r.has("export_found")) v.export_found = r.at("export_found").boolean();
  v.export_file = r.string_or("export_file", "");
  if (r.has("listened")) {
    v.listened = r.at("listened").boolean();
    v.trigger_host = r.string_or("trigger_host", "");
    if (r.has("any_sender")) v.any_sender = r.at("any_sender").boolean();
    if (r.has("refused_datagrams")) v.refused_datagrams = count(r, "refused_datagrams");
    if (r.has("refused_hosts")) {
      const JsonReader hosts = r.at("refused_hosts");
      for (size_t i = 0; i < hosts.array_size(); ++i) v.refused_hosts.push_back(hosts.at(i).string());
    }
  }
  return v;
}

}  // namespace

json quality_to_json(const QualityReport& report) {
  json fingers = json::object();
  for (size_t k = 0; k < report.finger_seen_fraction.size() && k < kNumDigits; ++k) {
    fingers[std::string(digit_name(static_cast<int>(k)))] = number_or_null(report.finger_seen_fraction[k]);
  }
  json devices = json::array();
  for (const DeviceQuality& d : report.devices) devices.push_back(quality_device_to_json(d));
  json rom = nullptr;
  if (report.rom) {
    rom = json{{"joint", report.rom->joint},
               {"expected_deg", report.rom->expected_deg},
               {"reached_deg", number_or_null(report.rom->reached_deg)}};
  }
  return json{{"verdict", report.verdict},
              {"reasons", report.reasons},
              {"duration_s", report.duration_s},
              {"planned_s", report.planned_s},
              {"hand_fraction", report.hand_fraction},
              {"devices", devices},
              {"finger_seen_fraction", fingers},
              {"rom", rom},
              {"vicon", vicon_to_json(report.vicon)}};
}

QualityReport quality_from_json(const json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.only_keys({"verdict", "reasons", "duration_s", "planned_s", "hand_fraction", "devices", "finger_seen_fraction",
               "rom", "vicon"});
  QualityReport report;
  report.verdict = r.string("verdict");
  if (report.verdict != "pass" && report.verdict != "warn" && report.verdict != "fail") {
    r.at("verdict").fail("expected \"pass\", \"warn\" or \"fail\", not \"" + report.verdict + "\"");
  }
  const JsonReader reasons = r.at("reasons");
  for (size_t i = 0; i < reasons.array_size(); ++i) report.reasons.push_back(reasons.at(i).string());
  report.duration_s = r.number("duration_s");
  report.planned_s = r.number("planned_s");
  report.hand_fraction = r.number("hand_fraction");
  const JsonReader devices = r.at("devices");
  for (size_t i = 0; i < devices.array_size(); ++i) report.devices.push_back(device_from_json(devices.at(i)));

  // The five fingers by name, each a share or null (never in view because the hand never was).
  const JsonReader fingers = r.at("finger_seen_fraction");
  fingers.only_keys({"thumb", "index", "middle", "ring", "pinky"});
  if (!fingers.json().empty()) {
    for (int k = 0; k < kNumDigits; ++k) {
      const std::string name(digit_name(k));
      fingers.at(name.c_str());  // present, even if null: a report names all five or none
      report.finger_seen_fraction.push_back(number_or_nan(fingers, name.c_str()));
    }
  }

  if (r.has("rom")) {
    const JsonReader rom = r.at("rom");
    rom.only_keys({"joint", "expected_deg", "reached_deg"});
    report.rom = RomQuality{rom.string("joint"), rom.number("expected_deg"), number_or_nan(rom, "reached_deg")};
  }
  report.vicon = vicon_from_json(r.at("vicon"));
  return report;
}

}  // namespace lmc
