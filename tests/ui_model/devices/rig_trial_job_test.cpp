// The Devices tab's test recording job owns what it records from: its worker shares the hub, so
// the hub's owner may let it go mid-trial; the trial then ends on its stop token and the hub goes
// with the worker.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "core/io/layout_json.h"
#include "devices/device_hub.h"
#include "devices/source_factory.h"
#include "tests/support/reference_data.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/devices/rig_trial_job.h"

namespace lmc::ui {
namespace rig_trial_job_test {  // named: test files share unity batches

TEST(RigTrialJob, TheWorkerKeepsTheHubItRecordsFromAfterItsOwnerLetsGo) {
  const std::filesystem::path dir = test::fresh_test_dir("rig_trial_job");
  const Layout layout = load_layout(test::asset_file("layouts/paper-initial.json"));
  auto hub = std::make_shared<devices::DeviceHub>(layout);
  devices::SourceSettings settings;
  settings.layout = layout;
  hub->add_source(devices::make_source(devices::parse_source_spec("sim"), settings));
  hub->start();
  const std::weak_ptr<devices::DeviceHub> watch = hub;
  RigTrialJob job;
  devices::TrialEngineConfig config;
  config.output_dir = dir;
  config.trial = "hub_kept";
  config.seconds = 60;
  config.backend = "sim";
  job.start(hub, nullptr, config);
  hub.reset();  // the owner lets go while the trial records
  EXPECT_FALSE(watch.expired()) << "the worker holds the hub";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!(job.snapshot() && job.snapshot()->recorder.frames_written > 20) &&
         std::chrono::steady_clock::now() < deadline) {
    job.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(job.snapshot());
  EXPECT_GT(job.snapshot()->recorder.frames_written, 20) << "frames still arrive from the hub nobody else holds";
  job.request_stop();
  job.cancel_and_join();
  EXPECT_TRUE(watch.expired()) << "the hub goes with the worker";
  ASSERT_TRUE(job.result());
  EXPECT_EQ(job.result()->outcome, devices::TrialOutcome::kInterrupted);
  std::filesystem::remove_all(dir);
}

}  // namespace rig_trial_job_test
}  // namespace lmc::ui
