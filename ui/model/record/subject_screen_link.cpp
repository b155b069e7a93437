#include "ui/model/record/subject_screen_link.h"

#include <cctype>

namespace lmc::ui {

std::optional<SubjectScreenRequest> parse_subject_screen_arg(const std::string& arg, std::string& error) {
  SubjectScreenRequest r;
  if (arg.empty()) return r;
  if (arg == "window") {
    r.windowed = true;
    return r;
  }
  bool digits = arg.size() <= 2;
  for (char ch : arg) digits = digits && std::isdigit(static_cast<unsigned char>(ch)) != 0;
  if (!digits) {
    error = "--subject-screen: '" + arg + "' is neither a monitor number (0 = the primary) nor 'window'";
    return std::nullopt;
  }
  r.monitor = std::stoi(arg);
  return r;
}

void apply_subject_screen_request(SubjectScreenLink& link, const SubjectScreenRequest& request) {
  link.open = true;
  link.monitor = request.monitor;
  if (request.windowed) {
    link.windowed = true;
  } else if (request.monitor >= 0) {
    link.windowed = false;
  } else {
    link.windowed.reset();
  }
}

bool subject_screen_windowed(const SubjectScreenLink& link) {
  // Covering the only monitor would hide the operator's own window: a window whatever was chosen.
  if (link.monitors.size() < 2) return true;
  if (link.windowed) return *link.windowed;
  return false;
}

}  // namespace lmc::ui
