// The BIDS export's names and file contents (core/export/bids_names.h, bids_motion_files.h,
// bids_dataset_files.h) from a small hand-made processed trial: labels keep letters and digits
// only, the run index is the trial name's digits, the entities come in BIDS order, each tracking
// system gets its own channels (three POS rows per point, mm, world frame) and motion rows with
// n/a where a point is missing, motion.json carries the keys BIDS-motion defines, events and
// participants read back as written, and no operator field reaches participants.tsv.
#include <gtest/gtest.h>

#include <sstream>

#include "core/export/bids_dataset_files.h"
#include "core/export/bids_motion_files.h"
#include "core/export/bids_names.h"
#include "core/export/trial_points.h"
#include "core/hand/hand_frame.h"

namespace lmc {
namespace bids_files_test {  // named: test files share unity batches

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, '\t');) cells.push_back(cell);
  return cells;
}

// Three frames; the fused hand has no data in frame 1; LMC1 and LMC3 (no LMC2); two Vicon markers.
PointTable small_table() {
  TrialAnalysis r;
  r.tag.trial = "Naiv_Index102";
  r.world.frame_count = 3;
  r.world.step_us = 10000.0;
  r.fused = HandTrack(3);
  for (int id : {1, 3}) r.world.devices.push_back({id, HandTrack(3)});
  for (int f = 0; f < 3; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      if (f != 1) r.fused.at(f, i) = Vec3(1.0 + i, 2.0 * f, -3.5);
      r.world.devices[0].track.at(f, i) = Vec3(10.0, 20.0 + f, 30.0 + i);
      r.world.devices[1].track.at(f, i) = Vec3(-1.25, 0.0, 0.5);
    }
  }
  r.has_vicon = true;
  MarkerSeries m;
  m.names = {"RFIN", "Subj:RWRA"};
  for (int f = 0; f < 3; ++f) m.positions.push_back({Vec3(100.0, 200.0 + f, 300.0), Vec3(5.0, 6.0, 7.0)});
  return trial_point_table(r, &m, ExportAxes::kWorld);
}

TEST(BidsNames, LabelsEntitiesAndRunIndex) {
  EXPECT_EQ(bids_label("S_01"), "S01");
  EXPECT_EQ(bids_label("S-01"), "S01");
  EXPECT_EQ(bids_label("Naiv"), "Naiv");
  EXPECT_EQ(bids_label("_-_"), "");
  EXPECT_EQ(bids_run_index(1, 2), 102);
  EXPECT_EQ(bids_run_index(2, 10), 210);
  EXPECT_EQ(bids_stem({"S01", "Index", "LMC1", "Naiv", 102, ""}), "sub-S01_task-Index_tracksys-LMC1_acq-Naiv_run-102");
  EXPECT_EQ(bids_stem({"S01", "Index", "", "Naiv", 102, ""}), "sub-S01_task-Index_acq-Naiv_run-102");
  // A subject's second session: the session entity right after the subject, as BIDS orders them.
  EXPECT_EQ(bids_stem({"S01", "Index", "LMC1", "Naiv", 102, "2"}),
            "sub-S01_ses-2_task-Index_tracksys-LMC1_acq-Naiv_run-102");
  EXPECT_EQ(bids_session_dir("S01", "2"), "sub-S01/ses-2");
  EXPECT_EQ(bids_session_dir("S01", ""), "sub-S01");
  EXPECT_EQ(bids_subject_dir("01"), "sub-01");
  EXPECT_EQ(bids_device_tracksys(4), "LMC4");
  EXPECT_EQ(bids_anonymous_label(0, 3), "01");
  EXPECT_EQ(bids_anonymous_label(11, 12), "12");
  EXPECT_EQ(bids_anonymous_label(4, 120), "005");
}

TEST(BidsMotionFiles, OneTrackingSystemPerPrefixWithItsOwnPoints) {
  const PointTable t = small_table();
  const std::vector<BidsTrackingSystem> systems = bids_tracking_systems(t);
  ASSERT_EQ(systems.size(), 4u);
  EXPECT_EQ(systems[0].name, "LMCfused");
  EXPECT_EQ(systems[1].name, "LMC1");
  EXPECT_EQ(systems[1].device_id, 1);
  EXPECT_EQ(systems[2].name, "LMC3");
  EXPECT_EQ(systems[3].name, "Vicon");
  for (int s = 0; s < 3; ++s) EXPECT_EQ(systems[static_cast<size_t>(s)].columns.size(), 28u);
  EXPECT_EQ(systems[0].tracked_points.front(), "Palm");
  EXPECT_EQ(systems[2].tracked_points.back(), "Pinky_End");
  EXPECT_EQ(systems[3].tracked_points, (std::vector<std::string>{"RFIN", "Subj_RWRA"}));
}

TEST(BidsMotionFiles, ChannelsAndMotionRowsAsDocumented) {
  const PointTable t = small_table();
  const std::vector<BidsTrackingSystem> systems = bids_tracking_systems(t);
  const std::vector<std::string> channels = lines_of(bids_channels_tsv(t, systems[1]));
  ASSERT_EQ(channels.size(), 1u + 3 * 28);
  EXPECT_EQ(channels[0], "name\tcomponent\ttype\ttracked_point\tunits\treference_frame\tdescription");
  EXPECT_EQ(cells_of(channels[1]),
            (std::vector<std::string>{"Palm_x", "x", "POS", "Palm", "mm", "world", "LMC1 realigned: palm position"}));
  EXPECT_EQ(cells_of(channels[3])[0], "Palm_z");
  EXPECT_EQ(cells_of(channels[3])[1], "z");
  EXPECT_EQ(cells_of(channels[84])[0], "Pinky_End_z");

  // No header: three rows of 84 numbers; LMC1's palm at (10, 20 + f, 30 + palm index).
  const std::vector<std::string> rows = lines_of(bids_motion_tsv(t, systems[1]));
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> row2 = cells_of(rows[2]);
  ASSERT_EQ(row2.size(), 84u);
  EXPECT_EQ(row2[0], "10.000");
  EXPECT_EQ(row2[1], "22.000");
  EXPECT_EQ(row2[2], "30.000");
  // The fused hand is missing in frame 1: every cell n/a, never 0; frame 0 has numbers.
  const std::vector<std::string> fused = lines_of(bids_motion_tsv(t, systems[0]));
  for (const auto& cell : cells_of(fused[1])) EXPECT_EQ(cell, "n/a");
  EXPECT_EQ(cells_of(fused[0])[0], "1.000");
  EXPECT_EQ(cells_of(fused[0])[2], "-3.500");
  // Vicon: the two markers, in the file's order.
  EXPECT_EQ(cells_of(lines_of(bids_motion_tsv(t, systems[3]))[1]),
            (std::vector<std::string>{"100.000", "201.000", "300.000", "5.000", "6.000", "7.000"}));
  EXPECT_EQ(bids_channels_json()["reference_frame"]["Levels"]["world"]["SpatialAxes"], "RSP");
}

TEST(BidsMotionFiles, MotionJsonHasTheSidecarKeys) {
  const PointTable t = small_table();
  const std::vector<BidsTrackingSystem> systems = bids_tracking_systems(t);
  BidsMotionInfo info;
  info.task_name = "Index";
  info.instructions = "Bend your index finger";
  info.tracking_system_name = "the Leap Motion Controller in slot LMC3";
  info.manufacturer = "Ultraleap";
  info.model = "Leap Motion Controller";
  info.serial = "LP123";
  info.software_versions = "lmc-workbench 0.1.0";
  const nlohmann::json j = bids_motion_json(t, systems[2], info);
  EXPECT_EQ(j["TaskName"], "Index");
  EXPECT_EQ(j["SamplingFrequency"], 100.0);
  EXPECT_DOUBLE_EQ(j["RecordingDuration"].get<double>(), 0.03);
  EXPECT_EQ(j["Manufacturer"], "Ultraleap");
  EXPECT_EQ(j["ManufacturersModelName"], "Leap Motion Controller");
  EXPECT_EQ(j["DeviceSerialNumber"], "LP123");
  EXPECT_EQ(j["TrackingSystemName"], "the Leap Motion Controller in slot LMC3");
  EXPECT_EQ(j["SoftwareVersions"], "lmc-workbench 0.1.0");
  EXPECT_EQ(j["MissingValues"], "n/a");
  EXPECT_EQ(j["TrackedPointsCount"], 28);
  EXPECT_EQ(j["POSChannelCount"], 84);
  EXPECT_FALSE(j.contains("TaskDescription"));  // empty: left out
  info.serial.clear();
  EXPECT_FALSE(bids_motion_json(t, systems[0], info).contains("DeviceSerialNumber"));
}

TEST(BidsDatasetFiles, EventsParticipantsScansAndDescription) {
  EXPECT_EQ(bids_events_tsv({{-0.0104, 3.0, "go"}, {2.5, 0.0, "stop"}}),
            "onset\tduration\ttrial_type\n-0.010\t3.000\tgo\n2.500\t0.000\tstop\n");
  const std::string participants =
      bids_participants_tsv({{"S01", "right", 185.0, std::nullopt}, {"02", "left", std::nullopt, 80.5}});
  EXPECT_EQ(participants,
            "participant_id\thandedness\thand_length_mm\thand_breadth_mm\nsub-S01\tright\t185.0\tn/a\nsub-02\tleft\tn/"
            "a\t80.5\n");
  const nlohmann::json pj = bids_participants_json();
  EXPECT_EQ(pj["hand_length_mm"]["Units"], "mm");
  EXPECT_FALSE(pj.contains("operator"));
  EXPECT_EQ(bids_scans_tsv({{"motion/a_motion.tsv", "2026-11-27T16:42:03.552000Z"}, {"motion/b_motion.tsv", ""}}),
            "filename\tacq_time\nmotion/a_motion.tsv\t2026-11-27T16:42:03.552000Z\nmotion/b_motion.tsv\tn/a\n");
  EXPECT_EQ(bids_acq_time("2026-11-27T16:42:03.552Z"), "2026-11-27T16:42:03.552000Z");
  EXPECT_EQ(bids_acq_time("yesterday"), "");
  const nlohmann::json d = bids_dataset_description("x");
  EXPECT_EQ(d["BIDSVersion"], "1.9.0");
  EXPECT_EQ(d["GeneratedBy"][0]["Name"], "lmc-workbench");
  EXPECT_EQ(d["GeneratedBy"][0]["Version"], LMC_VERSION);
  EXPECT_TRUE(bids_dataset_is_ours(d));
  EXPECT_FALSE(bids_dataset_is_ours({{"Name", "other"}}));
  EXPECT_EQ(bids_ignore(), "layouts/\n");
}

}  // namespace bids_files_test
}  // namespace lmc
