// What a trial's recorder sidecar gives its BIDS files (core/export/bids_trial_sidecar.h), from a
// hand-made sidecar: go, stop and the Vicon trigger as seconds from the grid's first row in onset
// order (no go when the sidecar predates the trial window), the acquisition time (none when
// anonymised), and each tracking system's maker, model and serial.
#include <gtest/gtest.h>

#include "core/export/bids_names.h"
#include "core/export/bids_trial_sidecar.h"

namespace lmc {
namespace bids_trial_sidecar_test {  // named: test files share unity batches

// Two controllers: LMC1 wrote rows from 1.020 s to 4.000 s, LMC2 from 1.010 s to 3.990 s (device
// clock); CaptureStart reached the controllers at 1.000 s.
RecorderSidecar sidecar() {
  RecorderSidecar s;
  s.software_name = "lmc-workbench";
  s.software_version = "0.0.9";
  s.backend = "leapc";
  s.host_start_utc = "2026-11-27T10:00:00.000Z";
  s.trial_window = {{"go_host_ns", 123}, {"go_host_utc", "2026-11-27T10:00:03.250Z"}};
  SidecarDevice a;
  a.device_id = 1;
  a.serial = "LP11111";
  a.frames_written = 90;
  a.first_timestamp_us = 1'020'000;
  a.last_timestamp_us = 4'000'000;
  SidecarDevice b = a;
  b.device_id = 2;
  b.serial = "LP22222";
  b.first_timestamp_us = 1'010'000;
  b.last_timestamp_us = 3'990'000;
  s.devices = {a, b};
  s.vicon_alignment = {{"devices", {{{"device_id", 1}, {"device_clock_at_event_us", 1'000'000}}}}};
  return s;
}

TEST(BidsTrialSidecar, EventsAreSecondsFromTheFirstRow) {
  const RecorderSidecar s = sidecar();
  const std::vector<BidsEvent> e = bids_trial_events(1'005'000, &s);  // the grid starts at 1.005 s
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].type, "vicon_capture_start");
  EXPECT_NEAR(e[0].onset_s, -0.005, 1e-9);
  EXPECT_EQ(e[1].type, "go");
  EXPECT_NEAR(e[1].onset_s, 0.005, 1e-9);
  EXPECT_NEAR(e[1].duration_s, 2.990, 1e-9);
  EXPECT_EQ(e[2].type, "stop");
  EXPECT_NEAR(e[2].onset_s, 2.995, 1e-9);
  EXPECT_EQ(bids_events_tsv(e),
            "onset\tduration\ttrial_type\n-0.005\t0.000\tvicon_capture_start\n0.005\t2.990\tgo\n2.995\t0.000\tstop\n");

  // A sidecar from before the trial window: its first row is the recorder's start, not go.
  RecorderSidecar old = s;
  old.trial_window = nullptr;
  old.vicon_alignment = nullptr;
  const std::vector<BidsEvent> only_stop = bids_trial_events(1'005'000, &old);
  ASSERT_EQ(only_stop.size(), 1u);
  EXPECT_EQ(only_stop[0].type, "stop");
  EXPECT_TRUE(bids_trial_events(0, nullptr).empty());
}

TEST(BidsTrialSidecar, AcquisitionTimeIsGoUnlessAnonymised) {
  const RecorderSidecar s = sidecar();
  EXPECT_EQ(bids_trial_acq_time(&s, false), "2026-11-27T10:00:03.250000Z");
  EXPECT_EQ(bids_trial_acq_time(&s, true), "");
  RecorderSidecar old = s;
  old.trial_window = nullptr;
  EXPECT_EQ(bids_trial_acq_time(&old, false), "2026-11-27T10:00:00.000000Z");
}

TEST(BidsTrialSidecar, MotionInfoPerTrackingSystem) {
  const RecorderSidecar s = sidecar();
  BidsTrialPlan t;
  t.motion = "Index";
  t.subject_cue = "Bend your index finger";
  t.operator_cue = "Index flexion";
  BidsTrackingSystem lmc2{bids_device_tracksys(2), 2, {}, {}};
  const BidsMotionInfo c = bids_motion_info(t, lmc2, &s, FusionMethod::kDefault);
  EXPECT_EQ(c.task_name, "Index");
  EXPECT_EQ(c.instructions, "Bend your index finger");
  EXPECT_EQ(c.task_description, "Index flexion");
  EXPECT_EQ(c.manufacturer, "Ultraleap");
  EXPECT_EQ(c.model, "Leap Motion Controller");
  EXPECT_EQ(c.serial, "LP22222");
  EXPECT_EQ(c.software_versions,
            "recorded with lmc-workbench 0.0.9 (leapc backend); processed with lmc-workbench " LMC_VERSION);
  BidsTrackingSystem fused{kBidsFusedTracksys, 0, {}, {}};
  const BidsMotionInfo f = bids_motion_info(t, fused, &s, FusionMethod::kReference);
  EXPECT_EQ(f.serial, "");
  EXPECT_NE(f.tracking_system_name.find("reference method"), std::string::npos);
  BidsTrackingSystem vicon{kBidsViconTracksys, 0, {}, {}};
  const BidsMotionInfo v = bids_motion_info(t, vicon, &s, FusionMethod::kDefault);
  EXPECT_EQ(v.manufacturer, "Vicon");
  EXPECT_EQ(v.model, "");  // not known for a real Vicon: left out of motion.json
  // A newer sidecar that records the controller's model is believed.
  RecorderSidecar newer = s;
  newer.devices[1].unknown["model"] = "Leap Motion Controller 2";
  EXPECT_EQ(bids_motion_info(t, lmc2, &newer, FusionMethod::kDefault).model, "Leap Motion Controller 2");
}

}  // namespace bids_trial_sidecar_test
}  // namespace lmc
