#pragma once
// How a trial's status and a verdict look in the Record tab: one icon, one colour and one word
// each, so the trial list, the verdict and the subject screen agree.
#include <imgui.h>

#include <string>

#include "core/session/session_state.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

struct StatusLook {
  const char* icon;  // ASCII: the default font has no symbols
  const char* word;
  ImVec4 colour;
};

inline ImVec4 verdict_colour(const std::string& verdict) {
  if (verdict == "pass") return palette::kOk;
  if (verdict == "warn") return palette::kWarning;
  if (verdict == "fail") return palette::kFail;
  return palette::kMuted;
}

inline StatusLook trial_status_look(const TrialState& t, bool recording_now) {
  const ImVec4 grey = palette::kMuted;
  if (recording_now || t.status == TrialStatus::kRecording) return {"(o)", "recording", palette::kRecording};
  const std::string verdict = t.attempts.empty() ? std::string() : t.attempts.back().verdict();
  switch (t.status) {
    case TrialStatus::kPending:
      return t.attempts.empty() ? StatusLook{" - ", "pending", grey} : StatusLook{" ~ ", "to record again", grey};
    case TrialStatus::kInterrupted:
      return {" ! ", "interrupted", palette::kAttention};
    case TrialStatus::kFailed:
      return {" x ", "fail", verdict_colour("fail")};
    case TrialStatus::kRecorded:
      return {" ? ", "recorded", verdict_colour(verdict)};
    case TrialStatus::kAccepted:
      return verdict == "warn"   ? StatusLook{" v ", "accepted (warn)", verdict_colour("warn")}
             : verdict == "fail" ? StatusLook{" v ", "accepted by the operator (fail)", verdict_colour("fail")}
                                 : StatusLook{" v ", "accepted (pass)", verdict_colour("pass")};
    default:
      break;
  }
  return {" ? ", "?", grey};
}

}  // namespace lmc::ui
