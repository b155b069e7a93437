#pragma once
// One trial of the TrialEngine (devices/record/trial_engine.h) on a worker thread, for the
// workbench (docs/architecture.md, ui/model/jobs/background_job.h): the engine runs on a jthread with
// the job's stop token, its status snapshots come back through the job's locked channel, and an
// exception becomes the Failed state. Stop = request_stop: the engine ends the trial as
// "interrupted" and keeps every row written. The UI thread calls poll() once a frame and reads
// the latest snapshot, the messages since the last poll and, at the end, the engine's result.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "devices/device_hub.h"
#include "devices/record/trial_engine.h"
#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

class RigTrialJob {
 public:
  RigTrialJob() = default;
  ~RigTrialJob() { job_.cancel_and_join(); }
  RigTrialJob(const RigTrialJob&) = delete;
  RigTrialJob& operator=(const RigTrialJob&) = delete;

  // The worker shares ownership of `hub`, so nothing it records from can go away under it
  // whatever order its owner lets go in. `sim`: null unless the trial should run in simulated
  // time, then a source the hub plays (the hub owns it, and the worker the hub).
  void start(std::shared_ptr<devices::DeviceHub> hub, devices::SimSource* sim, devices::TrialEngineConfig config);
  void request_stop() { job_.cancel(); }
  void cancel_and_join() { job_.cancel_and_join(); }

  // Drains the worker's snapshots (keeps the latest) and collects their messages. UI thread.
  void poll();

  bool running() const { return job_.running(); }
  JobState state() const { return job_.state(); }
  const std::string& trial() const { return trial_; }
  // Latest status from the engine (nullopt before the first one arrives).
  const std::optional<devices::TrialSnapshot>& snapshot() const { return snapshot_; }
  // The engine's result once the job has finished (Completed or Cancelled); null before, and
  // null when the job failed (then error() says why).
  std::shared_ptr<const devices::TrialResult> result() const { return job_.result(); }
  std::string error() const { return job_.error(); }
  // Device messages and engine notices since the last call.
  std::vector<std::string> take_messages();

 private:
  BackgroundJob<devices::TrialResult, devices::TrialSnapshot> job_;
  std::optional<devices::TrialSnapshot> snapshot_;
  std::vector<std::string> messages_;
  std::string trial_;
};

}  // namespace lmc::ui
