// Every background job honours its stop token: asked to stop, it does no more work and writes
// nothing it has not finished (the report, the exports), and a stopped run is reported as
// cancelled, never as a result.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <stop_token>
#include <thread>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/review/review_export.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/devices/calibration_job.h"
#include "ui/model/layout/layout_report_job.h"
#include "ui/model/layout/pose_set_store.h"
#include "ui/model/review/trial_view_job.h"

namespace lmc::ui {
namespace job_stop_test {  // named: test files share unity batches

std::stop_token stopped() {
  std::stop_source source;
  source.request_stop();
  return source.get_token();
}

bool wait_until(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  while (!done() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return done();
}

TEST(JobStop, ATrialViewAskedToStopReadsNothing) {
  lmc::TrialSources job;
  job.trial = "Naiv_Static101";
  job.lmc = test::scratch_dir("job_stop_view") / "no-such-recording.txt";  // reading it would throw
  const TrialView view = load_trial_view(job, BatchOptions{}, stopped());
  EXPECT_EQ(view.trial, "Naiv_Static101");
  EXPECT_EQ(view.result, nullptr);
  EXPECT_TRUE(view.series.trial.empty());
}

TEST(JobStop, APoseSetAskedToStopIsNotPrepared) {
  PoseSetChoice choice;
  choice.frames = 100;
  EXPECT_EQ(load_pose_set_for(choice, 1, stopped()), nullptr);
  const PoseSetPtr done = load_pose_set_for(choice, 2);
  ASSERT_NE(done, nullptr);
  EXPECT_EQ(done->prepared.size(), 100u);
}

TEST(JobStop, ReviewExportsAskedToStopWriteNothing) {
  const auto dir = test::scratch_dir("job_stop_exports") / "out";
  ReviewExportInput in;
  EXPECT_TRUE(write_review_exports(dir, in, stopped()).empty());
  EXPECT_FALSE(std::filesystem::exists(dir));
  TrialSeries series;
  series.trial = "T";
  EXPECT_TRUE(write_trial_export(dir, series, {}, "default", nlohmann::json::object(), false, stopped()).empty());
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(JobStop, ALayoutReportCancelledWhileBuildingWritesNoFile) {
  PoseSetChoice choice;
  choice.frames = 2000;  // long enough to build that the cancel lands before anything is written
  const PoseSetPtr poses = load_pose_set_for(choice, 1);
  const Layout layout = load_layout(test::asset_file("layouts/paper-initial.json"));
  const auto dir = test::scratch_dir("job_stop_report") / "report";
  LayoutReportJob job;
  job.start(layout, poses, dir);
  job.cancel();
  job.wait();
  EXPECT_EQ(job.state(), JobState::kCancelled);
  EXPECT_EQ(job.message(), "report cancelled");
  EXPECT_FALSE(std::filesystem::exists(dir / "report.md"));
}

TEST(JobStop, ACancelledCalibrationGivesNoCorrection) {
  const Layout layout = load_layout_or_preset("paper-initial");
  const devices::SimTrial trial = devices::generate_sim_trial(layout, devices::SimConfig{}, 5.0);
  LmcRecording rec;
  for (const auto& e : trial.events)
    if (e.is_frame) rec.rows.push_back(e.frame.frame);
  const auto file = test::scratch_dir("job_stop_calibration") / "LMC_Calibration01.raw.txt";
  save_lmc_recording(file, rec);
  CalibrationJob job;
  TrialCalibrationRequest request;
  request.trial = file;
  job.start(request, layout);
  job.cancel();  // lands while the trial is read or fitted
  ASSERT_TRUE(wait_until([&] { return job_finished(job.state()); }));
  EXPECT_EQ(job.state(), JobState::kCancelled);
  const auto outcome = job.outcome();
  EXPECT_TRUE(outcome == nullptr || outcome->result.devices.empty()) << "a stopped calibration still calibrated";
}

}  // namespace job_stop_test
}  // namespace lmc::ui
