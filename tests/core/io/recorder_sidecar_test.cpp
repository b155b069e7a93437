// The recorder's sidecar as one type: what it writes reads back equal, a crashed sidecar reads as
// incomplete, a mistyped value is an error that names the file and the JSON path, and keys a
// newer writer added survive a rewrite.
#include "core/io/recorder_sidecar.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/error.h"
#include "tests/support/build_paths.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

RecorderSidecar full_sidecar() {
  RecorderSidecar s;
  s.trial = "S01_index_1";
  s.status = "aborted";
  s.error = "Vicon refused";
  s.stopped_by = "operator (Ctrl-C)";
  s.software_name = "lmc-workbench";
  s.software_version = "9.9";
  s.backend = "sim";
  s.recording_file = "LMC_S01_index_1.raw.txt";
  s.recording_format = "raw";
  s.host_start_utc = "2026-11-23T10:00:00.000Z";
  s.host_stop_utc = "2026-11-23T10:00:05.000Z";
  s.host_start_ns = 1'000'000'000;
  s.host_stop_ns = 6'500'000'000;
  s.layout = {{"format", 1}, {"name", "paper-initial"}, {"devices", json::array({{{"slot", "LMC1"}}})}};
  s.serial_to_slot = {{"SIM-A", "LMC1"}, {"SIM-B", "LMC2"}};
  SidecarDevice d;
  d.device_id = 2;
  d.slot = "LMC2";
  d.serial = "SIM-B";
  d.frames_written = 120;
  d.frames_with_hand = 90;
  d.frames_dropped_queue = 1;
  d.frame_id_gaps = 3;
  d.first_timestamp_us = 5'000'000'000;
  d.last_timestamp_us = 5'004'000'000;
  SidecarGap gap;
  gap.from_timestamp_us = 5'001'000'000;
  gap.to_timestamp_us = 5'001'400'000;
  d.gaps.push_back(gap);
  SidecarDisconnect x;
  x.host_time_utc = "2026-11-23T10:00:01.000Z";
  x.host_ns = 2'000'000'000;
  x.message = "unplugged";
  x.reconnected_host_time_utc = "2026-11-23T10:00:01.400Z";
  x.event = "lost";
  x.serial = "SIM-B";
  x.slot = "LMC2";
  d.disconnects.push_back(x);
  s.devices.push_back(d);
  s.frames_written = 120;
  s.frames_dropped = 1;
  SidecarViconPacket p;
  p.type = "CaptureStart";
  p.packet_id = 4'000'000'001;  // beyond int: PacketIDs are time-based
  p.target = "127.0.0.1:30";
  p.datagrams_sent = 3;
  p.host_time_utc = "2026-11-23T10:00:00.100Z";
  p.host_ns = 1'100'000'000;
  p.warning = "state file not writable";
  s.vicon_packets.push_back(p);
  s.vicon_alignment = {{"event", "CaptureStart sent"}, {"packet_id", 4'000'000'001}};
  s.events = json::array({{{"event", "appeared"}, {"serial", "SIM-A"}}});
  SidecarGroundTruth t;
  t.file = "S01_index_1.trc";
  t.rate_hz = 100.0;
  t.frames = 500;
  t.device_clock_at_time_zero_us = 5'000'250'000;
  t.mapping = "assets/mappings/vicon-26-to-lmc.json (exact inverse)";
  s.ground_truth = t;
  s.extra = {{"simulator", {{"seed", 5}}}};
  return s;
}

TEST(RecorderSidecar, WhatIsWrittenReadsBackEqual) {
  const RecorderSidecar s = full_sidecar();
  const json j = recorder_sidecar_to_json(s);
  EXPECT_TRUE(is_recorder_sidecar(j));
  EXPECT_EQ(j.at("format"), "lmc-session");
  EXPECT_EQ(j.at("format_version"), 1);
  EXPECT_EQ(j.at("software"), json({{"name", "lmc-workbench"}, {"version", "9.9"}}));
  EXPECT_EQ(j.at("serial_to_slot"), json({{"SIM-A", "LMC1"}, {"SIM-B", "LMC2"}}));
  EXPECT_EQ(j.at("devices")[0].at("gaps")[0].at("duration_ms"), 400.0);
  EXPECT_FALSE(j.at("vicon_packets")[0].contains("error")) << "error is written only when sending failed";

  const RecorderSidecar back = recorder_sidecar_from_json(j, "mem.json");
  EXPECT_TRUE(back.complete());
  EXPECT_EQ(back.trial, "S01_index_1");
  EXPECT_EQ(back.status, "aborted");
  EXPECT_EQ(back.error, "Vicon refused");
  EXPECT_EQ(back.stopped_by, "operator (Ctrl-C)");
  EXPECT_EQ(back.software_version, "9.9");
  EXPECT_EQ(back.serial_to_slot, s.serial_to_slot);
  EXPECT_EQ(back.layout, s.layout);
  EXPECT_DOUBLE_EQ(back.host_duration_s(), 5.5);
  ASSERT_EQ(back.devices.size(), 1u);
  const SidecarDevice* d = back.device(2);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(back.device(1), nullptr);
  EXPECT_EQ(d->frames_written, 120);
  EXPECT_EQ(d->frame_id_gaps, 3);
  EXPECT_EQ(d->last_timestamp_us, 5'004'000'000);
  ASSERT_EQ(d->gaps.size(), 1u);
  EXPECT_DOUBLE_EQ(d->gaps[0].duration_ms(), 400.0);
  ASSERT_EQ(d->disconnects.size(), 1u);
  EXPECT_EQ(d->disconnects[0].reconnected_host_time_utc, "2026-11-23T10:00:01.400Z");
  EXPECT_EQ(d->disconnects[0].slot, "LMC2");
  ASSERT_EQ(back.vicon_packets.size(), 1u);
  EXPECT_EQ(back.vicon_packets[0].packet_id, 4'000'000'001);
  EXPECT_EQ(back.vicon_packets[0].warning, "state file not writable");
  ASSERT_TRUE(back.ground_truth.has_value());
  EXPECT_EQ(back.ground_truth->device_clock_at_time_zero_us, 5'000'250'000);
  EXPECT_EQ(back.ground_truth->frames, 500);
  EXPECT_EQ(back.extra, s.extra);
  EXPECT_EQ(back.events, s.events);
  // The second write is the same JSON as the first.
  EXPECT_EQ(recorder_sidecar_to_json(back), j);
}

TEST(RecorderSidecar, OptionalKeysAreLeftOutWhenUnset) {
  RecorderSidecar s;
  s.trial = "t";
  s.status = "completed";
  const json j = recorder_sidecar_to_json(s);
  for (const char* key : {"error", "stopped_by", "vicon_alignment", "vicon_trigger_received", "vicon_stop_received",
                          "ground_truth", "extra"})
    EXPECT_FALSE(j.contains(key)) << key;
  for (const char* key : {"host_stop_utc", "host_stop_ns", "devices", "frames_written", "vicon_packets", "events"})
    EXPECT_TRUE(j.contains(key)) << key;
}

TEST(RecorderSidecar, EachDevicesModelModeAndOtherSideHandsReadBackAndOldFilesStillRead) {
  RecorderSidecar s;
  s.trial = "t";
  s.status = "completed";
  SidecarDevice d;
  d.device_id = 2;
  d.slot = "LMC2";
  d.serial = "LP22222";
  d.model = "Leap Motion Controller 2";
  d.tracking_mode = "screen-top";
  d.frames_other_side_hand = 12;
  s.devices = {d};
  const json j = recorder_sidecar_to_json(s);
  EXPECT_EQ(j["devices"][0]["model"], "Leap Motion Controller 2");
  EXPECT_EQ(j["devices"][0]["tracking_mode"], "screen-top");
  EXPECT_EQ(j["devices"][0]["frames_other_side_hand"], 12);
  const RecorderSidecar back = recorder_sidecar_from_json(json::parse(j.dump()), "new.session.json");
  ASSERT_EQ(back.devices.size(), 1u);
  EXPECT_EQ(back.devices[0].model, "Leap Motion Controller 2");
  EXPECT_EQ(back.devices[0].tracking_mode, "screen-top");
  EXPECT_EQ(back.devices[0].frames_other_side_hand, 12);
  EXPECT_TRUE(back.devices[0].unknown.empty()) << "known keys, not kept as unknown";

  // A file written before these keys existed.
  json old = j;
  for (const char* key : {"model", "tracking_mode", "frames_other_side_hand"}) old["devices"][0].erase(key);
  const RecorderSidecar was = recorder_sidecar_from_json(old, "old.session.json");
  EXPECT_EQ(was.devices[0].model, "");
  EXPECT_EQ(was.devices[0].tracking_mode, "");
  EXPECT_EQ(was.devices[0].frames_other_side_hand, 0);
  EXPECT_FALSE(recorder_sidecar_to_json(was)["devices"][0].contains("model")) << "unknown model: left out";
}

TEST(RecorderSidecar, ViconListenRoundTripsAndIsAbsentFromOlderFiles) {
  RecorderSidecar s;
  s.trial = "t";
  s.status = "completed";
  EXPECT_FALSE(recorder_sidecar_to_json(s).contains("vicon_listen"));
  EXPECT_FALSE(recorder_sidecar_from_json(recorder_sidecar_to_json(s), "old.json").vicon_listen.has_value());
  SidecarViconListen l;
  l.address = "0.0.0.0:30 on eth0";
  l.binding = "listening on eth0 (10.0.0.2), the interface that reaches 10.0.0.5";
  l.allowed_senders = "10.0.0.5";
  l.trigger_host = "10.0.0.5";
  l.refused_datagrams = 7;
  l.refused_senders = {{"10.0.0.9", 4}, {"10.0.0.10", 3}};
  s.vicon_listen = l;
  const json j = recorder_sidecar_to_json(s);
  EXPECT_EQ(j.at("vicon_listen").at("refused_senders"), json({{"10.0.0.9", 4}, {"10.0.0.10", 3}}));
  EXPECT_FALSE(j.at("vicon_listen").contains("warning")) << "written only when there is one";
  const RecorderSidecar back = recorder_sidecar_from_json(j, "mem.json");
  ASSERT_TRUE(back.vicon_listen.has_value());
  EXPECT_EQ(back.vicon_listen->trigger_host, "10.0.0.5");
  EXPECT_EQ(back.vicon_listen->refused_datagrams, 7);
  EXPECT_FALSE(back.vicon_listen->any_sender);
  EXPECT_EQ(recorder_sidecar_to_json(back), j);
  // A mistyped count names its JSON path.
  json bad = j;
  bad["vicon_listen"]["refused_datagrams"] = "seven";
  try {
    recorder_sidecar_from_json(bad, "LMC_t.session.json");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/vicon_listen/refused_datagrams"), std::string::npos) << e.what();
  }
}

TEST(RecorderSidecar, ASidecarLeftAtRecordingReadsAsIncomplete) {
  // What the recorder writes at start: no stop time, no devices yet; a crash leaves it so.
  const json j = {{"format", "lmc-session"},
                  {"format_version", 1},
                  {"trial", "crashed"},
                  {"status", "recording"},
                  {"host_start_utc", "2026-11-23T10:00:00.000Z"},
                  {"host_start_ns", 1'000'000'000},
                  {"host_stop_utc", ""},
                  {"host_stop_ns", 0},
                  {"recording_file", "LMC_crashed.raw.txt"}};
  const RecorderSidecar s = recorder_sidecar_from_json(j, "LMC_crashed.session.json");
  EXPECT_FALSE(s.complete());
  EXPECT_EQ(s.trial, "crashed");
  EXPECT_TRUE(std::isnan(s.host_duration_s()));
  EXPECT_TRUE(s.devices.empty());
  EXPECT_EQ(s.frames_written, 0);
  EXPECT_FALSE(s.ground_truth.has_value());
  EXPECT_TRUE(s.layout.is_null());
}

TEST(RecorderSidecar, AMistypedFieldIsAnErrorNamingTheFileAndThePath) {
  const auto dir = test::scratch_dir("recorder_sidecar_mistyped");
  json j = recorder_sidecar_to_json(full_sidecar());
  j["devices"][0]["frames_written"] = "120";
  const auto path = dir / "LMC_bad.session.json";
  std::ofstream(path) << j.dump(2);
  try {
    (void)read_recorder_sidecar(path);
    ADD_FAILURE() << "a string frame count must not read";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, path.string());
    EXPECT_EQ(e.where().json_path, "/devices/0/frames_written");
    EXPECT_THAT(e.what(), HasSubstr("expected an integer"));
  }
  // Ground truth is written whole, so its clock is required.
  json k = recorder_sidecar_to_json(full_sidecar());
  k["ground_truth"].erase("device_clock_at_time_zero_us");
  try {
    (void)recorder_sidecar_from_json(k, "mem.json");
    ADD_FAILURE() << "a ground truth without its clock must not read";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().json_path, "/ground_truth/device_clock_at_time_zero_us");
  }
}

TEST(RecorderSidecar, OtherJsonIsNotASidecar) {
  const auto dir = test::scratch_dir("recorder_sidecar_layout");
  const auto path = dir / "layout.json";
  std::ofstream(path) << R"({"format": 1, "name": "x"})";
  EXPECT_FALSE(is_recorder_sidecar(json{{"format", 1}}));
  try {
    (void)read_recorder_sidecar(path);
    ADD_FAILURE() << "a layout is not a sidecar";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().json_path, "/format");
    EXPECT_THAT(e.what(), HasSubstr("lmc-session"));
  }
}

TEST(RecorderSidecar, UnknownKeysSurviveARoundTrip) {
  json j = recorder_sidecar_to_json(full_sidecar());
  j["operator"] = {{"name", "A. N. Other"}};
  j["devices"][0]["temperature_c"] = 41.5;
  j["vicon_packets"][0]["latency_ms"] = 2;
  j["ground_truth"]["markers"] = 26;
  const RecorderSidecar s = recorder_sidecar_from_json(j, "mem.json");
  EXPECT_EQ(s.unknown, json({{"operator", {{"name", "A. N. Other"}}}}));
  const json again = recorder_sidecar_to_json(s);
  EXPECT_EQ(again, j);
  EXPECT_EQ(again.at("devices")[0].at("temperature_c"), 41.5);
}

// The format's documentation (sessions/README.md) describes every key the table knows, so the two
// cannot drift apart: a key added to the table without a word about it fails here.
TEST(RecorderSidecar, SessionsReadmeDescribesEveryKey) {
  const std::string doc = test::read_text_file(test::source_dir() / "sessions" / "README.md");
  size_t keys = 0;
  for (const auto& [object, names] : recorder_sidecar_keys()) {
    for (const auto& key : names) {
      ++keys;
      const bool described =
          doc.find("`" + key + "`") != std::string::npos || doc.find("`" + key + "[]`") != std::string::npos;
      EXPECT_TRUE(described) << (object.empty() ? std::string("top level") : object) << ": " << key;
    }
  }
  EXPECT_GT(keys, 60u);
}

}  // namespace
}  // namespace lmc
