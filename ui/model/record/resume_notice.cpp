#include "ui/model/record/resume_notice.h"

namespace lmc::ui {

std::vector<std::string> resume_notice(const SessionState& st, const std::vector<std::string>& recovered) {
  std::vector<std::string> lines;
  for (const auto& name : recovered) {
    int attempt = 0;
    for (const auto& t : st.trials)
      if (t.plan.name == name) attempt = t.attempts.empty() ? 0 : t.attempts.back().number;
    lines.push_back(name +
                    " was cut off while recording: the program stopped (crash, kill or power loss). The rows "
                    "written until then are kept; recording it again moves them to superseded/" +
                    name + ".attempt" + std::to_string(attempt) + "/.");
  }
  const int total = static_cast<int>(st.trials.size());
  const int accepted = st.count(TrialStatus::kAccepted);
  std::string where = "Resumed: " + std::to_string(accepted) + " of " + std::to_string(total) + " trials accepted. ";
  const int next = st.next_trial();
  if (next < 0) {
    where += "Every trial is accepted; nothing is left to record.";
  } else {
    const auto& plan = st.trials.at(static_cast<size_t>(next)).plan;
    where += "It continues with trial " + std::to_string(next + 1) + " of " + std::to_string(total) + ", " + plan.name +
             " (layout " + plan.layout_key + "), after that layout's pre-flight.";
  }
  lines.push_back(where);
  return lines;
}

}  // namespace lmc::ui
