// The Devices tab's Calibrate step, model side: a simulated still-hand trial with one
// controller turned, calibrated on the worker, applied to the document as one undo step.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"
#include "ui/model/devices/calibration_job.h"
#include "ui/model/layout/layout_actions.h"

namespace calibration_job_test {

// Waits on a condition with a generous deadline (the worker runs under sanitizers in CI).
bool wait_until(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  while (!done() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return done();
}

}  // namespace calibration_job_test

TEST(CalibrationJob, CalibratesARecordedTrialAndAppliesAsOneUndoStep) {
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  lmc::devices::SimConfig config;
  config.calibration_rotations_deg["LMC2"] = Eigen::Vector3d(0, 6, 0);
  const lmc::devices::SimTrial trial = lmc::devices::generate_sim_trial(layout, config, 5.0);
  lmc::LmcRecording rec;
  for (const auto& e : trial.events)
    if (e.is_frame) rec.rows.push_back(e.frame.frame);
  const auto file = lmc::test::scratch_dir("calibration_job") / "LMC_Calibration01.raw.txt";
  lmc::save_lmc_recording(file, rec);

  lmc::ui::CalibrationJob job;
  lmc::TrialCalibrationRequest request;
  request.trial = file;
  job.start(request, layout);
  ASSERT_TRUE(calibration_job_test::wait_until([&] { return lmc::ui::job_finished(job.state()); }));
  ASSERT_EQ(job.state(), lmc::ui::JobState::kCompleted) << job.error();
  const auto outcome = job.outcome();
  ASSERT_NE(outcome, nullptr);
  EXPECT_LT(outcome->result.disagreement_after_mm, outcome->result.disagreement_before_mm);
  EXPECT_GT(outcome->result.disagreement_before_mm, 3.0);
  // LMC2 was turned; relative to the others it turns back the most.
  for (size_t d = 0; d < outcome->result.devices.size(); ++d) {
    if (d != 1) {
      EXPECT_LT(outcome->result.devices[d].turned_deg, outcome->result.devices[1].turned_deg);
    }
  }
  EXPECT_NE(outcome->table.find("LMC2"), std::string::npos);

  auto doc = lmc::ui::UndoableLayoutDocument(lmc::ui::make_document(layout));
  const auto before = doc.head();
  ASSERT_TRUE(lmc::ui::apply_calibration(doc, outcome->calibrated));
  EXPECT_EQ(doc.head().layout.name, "paper-initial (calibrated)");
  EXPECT_EQ(doc.undo_size(), 1u);
  doc.undo();
  EXPECT_EQ(doc.head(), before);
}
