#pragma once
// One line for the status bar and how it reads: the model that produced it says whether it is an
// error, so no one has to guess from its words.
#include <string>

namespace lmc::ui {

enum class Severity { kInfo, kError };

struct StatusReport {
  std::string text;
  Severity severity = Severity::kInfo;

  bool empty() const { return text.empty(); }
  bool is_error() const { return severity == Severity::kError; }
};

}  // namespace lmc::ui
