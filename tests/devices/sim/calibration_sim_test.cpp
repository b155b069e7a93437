// Calibration on the simulated rig: the simulator's rotational calibration error, a
// few of the seeded validation cases (all 50: `lmc calibrate --validate-sim 50`), swapped serials.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/calibration/rigid_transform.h"
#include "core/io/layout_json.h"
#include "devices/sim/calibration_validation.h"
#include "devices/sim/sim_rig.h"

namespace calibration_sim_test {

lmc::Layout paper_initial() {
  return lmc::load_layout_or_preset("paper-initial");
}

}  // namespace calibration_sim_test

TEST(SimCalibrationError, DefaultsKeepTodaysTranslationOnlyError) {
  const lmc::Layout layout = calibration_sim_test::paper_initial();
  const lmc::devices::SimRig rig(layout, lmc::devices::SimConfig{});
  for (int d = 0; d < layout.device_count(); ++d) {
    const Eigen::Isometry3d t = rig.true_device_to_world(d);
    EXPECT_LT((t.linear() - layout.devices[static_cast<size_t>(d)].pose.rotation()).norm(), 1e-12);
    EXPECT_LT((t.translation() - layout.devices[static_cast<size_t>(d)].pose.translation() -
               layout.devices[static_cast<size_t>(d)].offset_mm)
                  .norm(),
              1e-12);
  }
}

TEST(SimCalibrationError, RotationPerSlotAndSeededRandomErrorsComeFromTheConfig) {
  const lmc::Layout layout = calibration_sim_test::paper_initial();
  const nlohmann::json j = {
      {"calibration", "none"}, {"calibration_rotations_deg", {{"LMC2", {0.0, 0.0, 7.0}}}}, {"seed", 3}};
  const lmc::devices::SimConfig c = lmc::devices::sim_config_from_json(j, "test.json");
  // The key survives a round trip through JSON.
  EXPECT_EQ(lmc::devices::sim_config_from_json(lmc::devices::sim_config_to_json(c), "again")
                .calibration_rotations_deg.at("LMC2"),
            Eigen::Vector3d(0, 0, 7));
  const lmc::devices::SimRig rig(layout, c);
  const Eigen::Matrix3d nominal = layout.devices[1].pose.rotation();
  EXPECT_NEAR(lmc::rotation_angle_deg(nominal.transpose() * rig.true_device_to_world(1).linear()), 7.0, 1e-9);
  EXPECT_NEAR(lmc::rotation_angle_deg(rig.true_device_to_world(0).linear()), 0.0, 1e-9);

  lmc::devices::CalibrationValidationOptions options;
  const lmc::devices::SimRig a(layout, lmc::devices::validation_sim_config(11, options));
  const lmc::devices::SimRig b(layout, lmc::devices::validation_sim_config(11, options));
  for (int d = 0; d < layout.device_count(); ++d) {
    EXPECT_TRUE(a.true_device_to_world(d).isApprox(b.true_device_to_world(d)));  // seeded: the same twice
    const lmc::Vec3 moved = a.true_device_to_world(d).translation() -
                            layout.devices[static_cast<size_t>(d)].pose.translation() -
                            layout.devices[static_cast<size_t>(d)].offset_mm;
    EXPECT_LE(moved.norm(), options.max_translation_mm + 1e-9);
    EXPECT_LE(lmc::rotation_angle_deg(layout.devices[static_cast<size_t>(d)].pose.rotation().transpose() *
                                      a.true_device_to_world(d).linear()),
              options.max_rotation_deg + 1e-9);
  }
  // A bad value names the key.
  try {
    (void)lmc::devices::sim_config_from_json({{"calibration_rotations_deg", {{"LMC1", {1.0, 2.0}}}}}, "bad.json");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("calibration_rotations_deg/LMC1"), std::string::npos) << e.what();
  }
}

// A handful of the validation cases (each records a 10 s trial and calibrates it twice).
TEST(SimCalibrationValidation, InjectedErrorsAreRecoveredWithinTheIssuesLimits) {
  const lmc::Layout layout = calibration_sim_test::paper_initial();
  lmc::devices::CalibrationValidationOptions options;
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    const auto c = lmc::devices::run_calibration_case(layout, seed, options);
    EXPECT_GT(c.injected_mm, 10.0) << seed;
    EXPECT_LT(c.vicon_mm, options.vicon_limit_mm) << seed;
    EXPECT_LT(c.vicon_deg, options.vicon_limit_deg) << seed;
    EXPECT_LT(c.consensus_mm, options.consensus_limit_mm) << seed;
    EXPECT_LT(c.consensus_deg, options.consensus_limit_deg) << seed;
    EXPECT_TRUE(c.warnings.empty()) << seed << ": " << c.warnings.front();
  }
}

TEST(SimCalibrationValidation, SwappedSerialsAreDetectedWithAndWithoutVicon) {
  const lmc::Layout layout = calibration_sim_test::paper_initial();
  for (const bool vicon : {true, false}) {
    const auto w = lmc::devices::swapped_serial_warnings(layout, 1, 2, 5, vicon);
    ASSERT_EQ(w.size(), 1U) << (vicon ? "with Vicon" : "without");
    EXPECT_NE(w[0].find("LMC2 and LMC3 look swapped"), std::string::npos) << w[0];
  }
}

// The Devices tab capture's rig (three controllers turned, every controller shifted up to 15 mm)
// on the start layout, paper-optimized-as-processed, where LMC1 stands ≈ 256 mm from the hand:
// every controller is found where it really stands, with the truth as Vicon and without Vicon.
// LMC1 reports its wrist, metacarpal bases and palm clamped on its +250 mm y cut in every frame
// (calibration_samples.h); before that was known to calibration it moved ≈ 100 mm and 20°.
// (Seed 2 turns LMC2 away from the hand: it is left as it was, which is another test's matter.)
TEST(SimCalibrationValidation, OptimizedLayoutAsProcessedIsRecoveredWithTheCapturesErrors) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-optimized-as-processed");
  lmc::devices::SimConfig sim;
  sim.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
  sim.calibration_rotations_deg["LMC3"] = Eigen::Vector3d(4, 0, 0);
  sim.calibration_rotations_deg["LMC4"] = Eigen::Vector3d(0, 0, -3);
  sim.calibration_random_translation_mm = 15;
  lmc::devices::CalibrationValidationOptions options;
  options.seconds = 5.0;                           // the Devices tab's still-hand trial
  for (const std::uint64_t seed : {1U, 3U, 4U}) {  // 1: the capture's
    sim.seed = seed;
    const auto c = lmc::devices::run_calibration_case(layout, sim, options);
    EXPECT_GT(c.injected_mm, 3.0) << seed;
    EXPECT_EQ(c.vicon_unfitted, 0) << seed;
    EXPECT_EQ(c.consensus_unfitted, 0) << seed;
    EXPECT_LT(c.vicon_mm, options.vicon_limit_mm) << seed;
    EXPECT_LT(c.vicon_deg, options.vicon_limit_deg) << seed;
    EXPECT_LT(c.consensus_mm, options.consensus_limit_mm) << seed;
    EXPECT_LT(c.consensus_deg, options.consensus_limit_deg) << seed;
    for (const auto& w : c.warnings) ADD_FAILURE() << seed << ": " << w;
  }
}
