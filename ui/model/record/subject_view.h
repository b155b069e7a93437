#pragma once
// What the subject screen shows, as plain data: the stage of the session, the big red
// circle while a trial records (the study: "the cue recording is a big red circle"), the countdown,
// the cue in large letters, the palm orientation and the motion pictogram. Built from the Record
// tab's model every frame; the subject window only draws it and never has controls. Nothing an
// operator reads (verdicts, devices, reasons) goes on the subject's screen.
#include <optional>
#include <string>

#include "core/session/protocol.h"
#include "devices/record/trial_engine.h"
#include "ui/model/record/motion_pictogram.h"

namespace lmc::ui {

class RecordState;

enum class SubjectStage { kNoSession, kGetReady, kWaiting, kCountdown, kRecording, kDone };

struct SubjectView {
  SubjectStage stage = SubjectStage::kNoSession;
  bool red_circle = false;  // only while the trial records
  std::string headline;     // "Welcome", "Get ready", "3", "Recording", "Thank you": never empty
  std::string cue;          // the trial type's subject cue, in large letters
  std::string pose_cue;     // how to hold the hand ("palm facing down")
  std::string time_text;    // "7 s left" while recording; "" otherwise
  std::optional<MotionPictogram> pictogram;
};

// The parts of the Record tab's state the subject screen depends on.
struct SubjectViewInputs {
  bool has_session = false;
  bool finished = false;            // every trial accepted
  const TrialType* type = nullptr;  // the current (or recording) trial's
  const ProtocolPose* pose = nullptr;
  std::string sim_motion;                          // the trial's "<pose>/<motion>"
  double hand_length_mm = 0, hand_breadth_mm = 0;  // the subject's, 0 when not measured
  std::optional<devices::TrialPhase> phase;        // set while a trial runs
  double countdown_remaining_s = 0, recording_s = 0;
};

// The countdown's number, for the subject's screen and the operator's alike (one source, so both
// show the same number at the same moment): the whole seconds still to wait, rounded up, so 0
// never shows before recording begins.
int countdown_number(double remaining_s);
// Whole seconds left of a trial of `duration_s` after `recording_s`, rounded up, for both screens.
int seconds_left(double duration_s, double recording_s);

SubjectViewInputs subject_view_inputs(const RecordState& model);
// `t_s` drives the pictogram's animation (any steadily increasing clock).
SubjectView build_subject_view(const SubjectViewInputs& in, double t_s);

}  // namespace lmc::ui
