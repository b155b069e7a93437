#include "core/session/session_trials.h"

#include "core/common/error.h"
#include "core/session/session_folder.h"
#include "core/session/trial_files.h"

namespace fs = std::filesystem;

namespace lmc {

std::vector<TrialSources> accepted_trial_jobs(const fs::path& dir, const std::optional<fs::path>& vicon_dir,
                                              std::vector<std::string>* notes) {
  const SessionState state = read_session_state(dir);
  std::vector<TrialSources> jobs;
  for (const auto& t : state.trials) {
    const std::string& name = t.plan.name;
    if (t.status != TrialStatus::kAccepted) {
      if (notes != nullptr) notes->push_back(name + ": " + trial_status_name(t.status) + ", not processed");
      continue;
    }
    const TrialFiles files = trial_files(dir, name);
    TrialSources job;
    job.trial = name;
    job.lmc = files.recording;
    if (!fs::exists(job.lmc)) {
      if (notes != nullptr) notes->push_back(name + ": accepted, but " + job.lmc.string() + " is missing");
      continue;
    }
    if (fs::exists(files.sidecar)) job.sidecar = files.sidecar;
    // The sidecar holds the layout the trial was recorded with; the manifest's copy of the
    // block's layout stands in when a crash left no sidecar.
    auto layout = state.setup.layouts.find(t.plan.layout_key);
    if (layout != state.setup.layouts.end()) job.layout_json = layout->second;
    for (const char* ext : {".trc", ".c3d", ".TRC", ".C3D"}) {
      const fs::path p = (vicon_dir ? *vicon_dir : dir) / (name + ext);
      if (fs::exists(p)) {
        job.vicon = p;
        break;
      }
    }
    jobs.push_back(job);
  }
  return jobs;
}

std::vector<TrialSources> trial_sources_for_input(const fs::path& input, const std::optional<fs::path>& vicon,
                                                  std::vector<std::string>* notes) {
  // A subject session folder is processed from its journal: only each trial's accepted attempt,
  // never the ones kept under superseded/ or trials still pending.
  const bool subject_session = is_session_folder(input);
  auto jobs = subject_session ? accepted_trial_jobs(input, vicon, notes) : discover_trials(input, vicon, notes);
  if (jobs.empty()) {
    throw Error(ErrorLocation(input.string()), subject_session
                                                   ? "the session has no accepted trial yet"
                                                   : "no LMC recordings (LMC_*.txt, Interp_LMC_*.txt) found");
  }
  return jobs;
}

}  // namespace lmc
