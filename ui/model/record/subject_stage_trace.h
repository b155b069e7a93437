#pragma once
// A line per change of what the subject screen shows, so a test that drives the real window can
// tell how long the subject saw the red circle: "<seconds since the first line> <stage> <circle
// 0|1> <trial seconds the previous stage reached>". Off unless given a file (the workbench takes
// LMC_SUBJECT_TRACE).
#include <filesystem>
#include <fstream>
#include <optional>

#include "ui/model/record/subject_view.h"

namespace lmc::ui {

const char* subject_stage_name(SubjectStage s);  // "no_session", "get_ready", "waiting", "countdown", …

class SubjectStageTrace {
 public:
  SubjectStageTrace() = default;
  explicit SubjectStageTrace(const std::filesystem::path& file);
  // `t_s`: a steady clock; `recording_s`: how far into the trial (0 outside one).
  void observe(const SubjectView& view, double recording_s, double t_s);

 private:
  std::ofstream out_;
  std::optional<SubjectStage> last_;
  bool last_circle_ = false;
  double last_recording_s_ = 0;
  double t0_s_ = 0;
};

}  // namespace lmc::ui
