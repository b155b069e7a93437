#include "ui/model/devices/rig_trial_job.h"

#include <utility>

namespace lmc::ui {

void RigTrialJob::start(std::shared_ptr<devices::DeviceHub> hub, devices::SimSource* sim,
                        devices::TrialEngineConfig config) {
  job_.cancel_and_join();
  snapshot_.reset();
  trial_ = config.trial;
  // The engine and its inputs live on the worker; only the channel is shared with the UI.
  job_.start([hub = std::move(hub), sim, cfg = std::move(config)](std::stop_token stop,
                                                                  JobChannel<devices::TrialSnapshot>& channel) {
    devices::TrialEngine engine(*hub, sim, cfg);
    return engine.run(stop, [&channel](const devices::TrialSnapshot& s) {
      channel.set_stage(devices::trial_phase_name(s.phase));
      channel.report(s);
    });
  });
}

void RigTrialJob::poll() {
  for (auto& s : job_.drain_reports()) {
    for (auto& m : s.new_messages) messages_.push_back(std::move(m));
    for (auto& m : s.new_notices) messages_.push_back(std::move(m));
    s.new_messages.clear();
    s.new_notices.clear();
    snapshot_ = std::move(s);
  }
}

std::vector<std::string> RigTrialJob::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

}  // namespace lmc::ui
