#include "ui/model/record/subject_stage_trace.h"

#include <cstdio>

namespace lmc::ui {

const char* subject_stage_name(SubjectStage s) {
  switch (s) {
    case SubjectStage::kNoSession:
      return "no_session";
    case SubjectStage::kGetReady:
      return "get_ready";
    case SubjectStage::kWaiting:
      return "waiting";
    case SubjectStage::kCountdown:
      return "countdown";
    case SubjectStage::kRecording:
      return "recording";
    case SubjectStage::kDone:
      return "done";
  }
  return "?";
}

SubjectStageTrace::SubjectStageTrace(const std::filesystem::path& file) : out_(file, std::ios::app) {}

void SubjectStageTrace::observe(const SubjectView& view, double recording_s, double t_s) {
  if (!out_.is_open()) return;
  if (last_ && *last_ == view.stage && last_circle_ == view.red_circle) {
    last_recording_s_ = recording_s;
    return;
  }
  if (!last_) t0_s_ = t_s;
  // The trial time the previous stage reached goes on the line that ends it: how far into the
  // trial the circle was still shown.
  char line[160];
  std::snprintf(line, sizeof line, "%.3f %s %d %.3f\n", t_s - t0_s_, subject_stage_name(view.stage),
                view.red_circle ? 1 : 0, last_recording_s_);
  out_ << line << std::flush;
  last_ = view.stage;
  last_circle_ = view.red_circle;
  last_recording_s_ = recording_s;
}

}  // namespace lmc::ui
