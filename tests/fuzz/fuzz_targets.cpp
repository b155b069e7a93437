#include "tests/fuzz/fuzz_targets.h"

#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/io/c3d.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/sensor_catalogue_json.h"
#include "core/io/trc.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/length_correction_json.h"
#include "core/processing/resample.h"
#include "core/session/protocol.h"
#include "core/session/session_folder.h"
#include "core/session/session_journal.h"
#include "devices/sim/sim_config.h"
#include "devices/vicon/vicon_message.h"
#include "devices/vicon/vicon_senders.h"

namespace lmc::fuzz {
namespace {

constexpr const char* kSource = "fuzz-input";

std::istringstream as_stream(std::string_view bytes) {
  return std::istringstream(std::string(bytes));
}

// The study's marker mapping, read from the assets once (it is not the input under test).
const ViconMapping& study_mapping() {
  static const ViconMapping mapping = default_vicon_mapping();
  return mapping;
}

// The recording as `lmc process` takes it: parsed, then put on the 100 Hz grid (the resampler is
// where a jumping timestamp once asked for gigabytes).
void lmc_recording(std::string_view bytes) {
  const LmcRecording rec = parse_lmc_recording_text(bytes, kSource);
  if (rec.kind == RecordingKind::kRaw)
    (void)resample_recording(rec);
  else
    (void)grid_from_resampled(rec);
}

// Vicon markers as `lmc process --vicon` takes them: the file, then the study's marker mapping.
void trc(std::string_view bytes) {
  const TrcData data = parse_trc_text(bytes, kSource);
  MarkerSeries series;
  series.names = data.marker_names;
  series.positions = data.positions;
  series.rate_hz = data.data_rate_hz;
  series.source = kSource;
  (void)apply_vicon_mapping(study_mapping(), series);
}

void c3d(std::string_view bytes) {
  const std::vector<std::uint8_t> raw(bytes.begin(), bytes.end());
  const C3dData data = parse_c3d(raw, kSource);
  (void)apply_vicon_mapping(study_mapping(), data.to_marker_series(kSource));
}

void layout_json(std::string_view bytes) {
  (void)layout_from_json(parse_json_text(std::string(bytes), kSource), kSource);
}

void pose_set_tsv(std::string_view bytes) {
  auto in = as_stream(bytes);
  (void)parse_pose_set(in, kSource);
}

void sim_config(std::string_view bytes) {
  (void)devices::sim_config_from_json(parse_json_text(std::string(bytes), kSource), kSource);
}

void recorder_sidecar(std::string_view bytes) {
  const nlohmann::json j = parse_json_text(std::string(bytes), kSource);
  if (is_recorder_sidecar(j)) (void)recorder_sidecar_from_json(j, kSource);
}

void vicon_mapping(std::string_view bytes) {
  (void)vicon_mapping_from_json(parse_json_text(std::string(bytes), kSource), kSource);
}

// Listen mode's parser never throws: it says no, with a reason.
void vicon_packet(std::string_view bytes) {
  std::string error;
  (void)devices::parse_vicon_message(bytes, &error);
}

void protocol(std::string_view bytes) {
  const Protocol p = protocol_from_json(parse_json_text(std::string(bytes), kSource), kSource);
  (void)plan_trials(p, 7);
}

// A session's journal as reopening reads it: lines, then the state its events make.
void session_journal(std::string_view bytes) {
  const JournalContents journal = parse_journal_text(bytes, kSource);
  (void)state_from_journal(journal, kSource);
}

// A sensor catalogue as the workbench reads assets/sensors/sensors.json (or a lab's own).
void sensor_catalogue(std::string_view bytes) {
  (void)sensor_catalogue_from_json(parse_json_text(std::string(bytes), kSource), kSource);
}

// A fitted length correction as `lmc process --length-correction` reads it.
void length_correction(std::string_view bytes) {
  (void)length_correction_from_json(parse_json_text(std::string(bytes), kSource), kSource);
}

// The operator's list of Vicon hosts (`--vicon-host`), then the check every datagram's sender
// meets. Names resolve without the network: "vicon*" to one address, anything else to none.
void vicon_hosts(std::string_view bytes) {
  const auto resolve = [](const std::string& name) -> std::vector<std::uint32_t> {
    if (name.rfind("vicon", 0) == 0) return {0x0A000007u};
    throw Error("host name '" + name + "' does not resolve");
  };
  const devices::ViconSenders senders = devices::ViconSenders::parse(std::string(bytes), resolve);
  (void)senders.describe();
  for (const std::uint32_t sender : {0x0A000007u, 0x7F000001u, 0xC0A80101u, 0xFFFFFFFFu}) (void)senders.allows(sender);
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"lmc_recording", "LMC raw / resampled / ray-traced text, then the resampler", lmc_recording},
      {"trc", "Vicon TRC, then the marker mapping", trc},
      {"c3d", "C3D, then the marker mapping", c3d},
      {"layout_json", "layout JSON", layout_json},
      {"pose_set_tsv", "pose-set TSV", pose_set_tsv},
      {"sim_config", "simulator config JSON", sim_config},
      {"recorder_sidecar", "recorder sidecar JSON", recorder_sidecar},
      {"vicon_mapping", "Vicon marker mapping JSON", vicon_mapping},
      {"vicon_packet", "Vicon UDP capture packet (listen mode)", vicon_packet},
      {"protocol", "session protocol JSON, then the trial plan", protocol},
      {"session_journal", "session journal (JSON lines), then the session state", session_journal},
      {"length_correction", "fitted length-correction JSON", length_correction},
      {"sensor_catalogue", "sensor catalogue JSON (models, fields of view, ranges)", sensor_catalogue},
      {"vicon_hosts", "the Vicon host list of listen mode (addresses, subnets, names)", vicon_hosts},
  };
  return all;
}

const Target* find_target(std::string_view name) {
  for (const auto& t : targets())
    if (name == t.name) return &t;
  return nullptr;
}

bool run_one(const Target& target, std::string_view bytes) {
  try {
    target.run(bytes);
    return true;
  } catch (const Error&) {
    return false;  // the expected answer to bad input: a message naming the source
  }
}

}  // namespace lmc::fuzz
