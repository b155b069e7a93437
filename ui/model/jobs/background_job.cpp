#include "ui/model/jobs/background_job.h"

namespace lmc::ui {

const char* job_state_name(JobState s) {
  switch (s) {
    case JobState::kIdle:
      return "idle";
    case JobState::kStarting:
      return "starting";
    case JobState::kRunning:
      return "running";
    case JobState::kCompleted:
      return "completed";
    case JobState::kCancelled:
      return "cancelled";
    case JobState::kFailed:
      return "failed";
  }
  return "?";
}

void JobGraveyard::reap() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->finished()) {
      it->thread.join();
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace lmc::ui
