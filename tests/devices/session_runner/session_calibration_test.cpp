// The calibration step at the start of a session block, on the simulated rig with
// controllers standing up to 30 mm and 4° away from where the layout says.
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/paths.h"
#include "core/io/layout_json.h"
#include "core/io/recorder_sidecar.h"
#include "core/session/session_folder.h"
#include "core/session/trial_files.h"
#include "devices/session_runner/session_runner.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"

namespace fs = std::filesystem;

namespace lmc::devices {
namespace session_calibration_test {

// The quick protocol with a 3 s calibration step per block.
fs::path calibrating_protocol(const fs::path& dir) {
  std::ifstream in(assets_dir() / "protocols" / "quick.json");
  nlohmann::json p = nlohmann::json::parse(in);
  p["name"] = "quick-calibrated";
  p["calibration"] = {{"duration_s", 3}};
  const fs::path out = dir / "quick-calibrated.json";
  std::ofstream(out) << p.dump(1);
  return out;
}

SessionFolder new_session(const fs::path& dir) {
  NewSessionSpec spec;
  spec.subject.subject_id = "S07";
  spec.protocol = calibrating_protocol(dir.parent_path()).string();
  spec.duration_override_s = 1.0;
  return SessionFolder::create(dir, spec);
}

SessionRunOptions misplaced_rig() {
  SessionRunOptions o;
  o.fast = true;
  o.sim.seed = 3;
  o.sim.calibration_random_translation_mm = 30;
  o.sim.calibration_random_rotation_deg = 4;
  return o;
}

Eigen::Isometry3d layout_device_to_world(const LayoutDevice& d) {
  Eigen::Isometry3d t = d.pose.device_to_world();
  t.translation() += d.offset_mm;
  return t;
}

TEST(SessionCalibration, ABlockCalibratesFromItsStillHandAndRecordsWithTheResult) {
  const fs::path root = test::scratch_dir("session_calibration");
  SessionFolder folder = new_session(root / "S07");
  const SessionRunOptions options = misplaced_rig();
  SessionRunner runner(folder, options);
  ASSERT_TRUE(runner.needs_calibration(0));
  const Layout nominal = runner.layout(0);

  const BlockCalibration c = runner.calibrate_block(0);
  ASSERT_TRUE(c.ok()) << c.failure;
  EXPECT_EQ(c.trial_name, "Calib_Naiv01");
  EXPECT_TRUE(c.fit->result.with_vicon) << "the simulator's truth beside the recording serves as Vicon";
  EXPECT_TRUE(c.warnings.empty()) << c.warnings.front();
  EXPECT_TRUE(fs::exists(folder.dir() / "LMC_Calib_Naiv01.raw.txt"));

  // Where the simulated controllers really stand: the session's one placement error.
  SimConfig truth_config = options.sim;
  truth_config.calibration_seed = options.sim.seed;
  const SimRig truth(nominal, truth_config);
  double worst_nominal = 0, worst_calibrated = 0;
  for (int d = 0; d < nominal.device_count(); ++d) {
    const Eigen::Vector3d real = truth.true_device_to_world(d).translation();
    worst_nominal = std::max(
        worst_nominal, (layout_device_to_world(nominal.devices[static_cast<size_t>(d)]).translation() - real).norm());
    worst_calibrated = std::max(
        worst_calibrated,
        (layout_device_to_world(c.fit->calibrated.devices[static_cast<size_t>(d)]).translation() - real).norm());
  }
  EXPECT_GT(worst_nominal, 10.0);
  EXPECT_LT(worst_calibrated, 3.0) << "nominal was " << worst_nominal << " mm off";

  runner.apply_calibration(c);
  EXPECT_FALSE(runner.needs_calibration(0));
  const auto& st = folder.state();
  EXPECT_EQ(st.calibration.at("Naiv").status, "applied");
  EXPECT_EQ(st.setup.layouts.at("Naiv").at("name"), c.fit->calibrated.name);
  EXPECT_EQ(st.nominal_layouts.at("Naiv").at("name"), nominal.name);
  EXPECT_EQ(runner.layout(0).name, c.fit->calibrated.name);

  // The block's trials carry the calibrated layout for processing.
  const AttemptResult r = runner.run_trial(0);
  EXPECT_EQ(r.outcome, "completed") << r.reason;
  const RecorderSidecar side = read_recorder_sidecar(trial_files(folder.dir(), runner.plan()[0].name).sidecar);
  EXPECT_EQ(side.layout.at("name"), c.fit->calibrated.name);
}

TEST(SessionCalibration, ACutOffCalibrationIsDoneAgainAndKeepingTheNominalLayoutIsJournaled) {
  const fs::path root = test::scratch_dir("session_calibration_resume");
  const fs::path dir = root / "S07";
  {
    SessionFolder folder = new_session(dir);
    folder.calibration_started("Naiv");  // and then the program died
  }
  SessionFolder folder = SessionFolder::open(dir);
  EXPECT_EQ(folder.state().calibration.at("Naiv").status, "recording");
  SessionRunner runner(folder, misplaced_rig());
  ASSERT_TRUE(runner.needs_calibration(0));
  const Layout nominal = runner.layout(0);
  const BlockCalibration c = runner.calibrate_block(0);
  EXPECT_EQ(c.attempt, 2);
  EXPECT_EQ(c.trial_name, "Calib_Naiv02");
  ASSERT_TRUE(c.ok()) << c.failure;
  runner.apply_calibration(c);
  runner.keep_nominal_layout(0, "the subject's hand moved", &c);
  const auto& cal = folder.state().calibration.at("Naiv");
  EXPECT_EQ(cal.status, "nominal");
  EXPECT_EQ(cal.reason, "the subject's hand moved");
  EXPECT_EQ(folder.state().setup.layouts.at("Naiv").at("name"), nominal.name);
  EXPECT_EQ(runner.layout(0).name, nominal.name);
  EXPECT_FALSE(runner.needs_calibration(0));
  // The manifest a lab reads says all of it.
  std::ifstream in(dir / "session.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest.at("calibration").at("Naiv").at("status"), "nominal");
  EXPECT_EQ(manifest.at("calibration").at("Naiv").at("trial"), "Calib_Naiv02");
  EXPECT_TRUE(manifest.at("nominal_layouts").contains("Naiv"));
}

TEST(SessionCalibration, ProtocolsWithoutTheStepNeverAskForIt) {
  const fs::path root = test::scratch_dir("session_calibration_none");
  NewSessionSpec spec;
  spec.subject.subject_id = "S08";
  spec.protocol = "quick";
  SessionFolder folder = SessionFolder::create(root / "S08", spec);
  SessionRunner runner(folder, misplaced_rig());
  EXPECT_FALSE(runner.needs_calibration(0));
  EXPECT_THROW(folder.calibration_started("Naiv"), Error);
}

}  // namespace session_calibration_test
}  // namespace lmc::devices
