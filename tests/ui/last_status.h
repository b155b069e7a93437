#pragma once
// A status bar for tests: keeps the last line a tab or panel reported and whether it was an error.
#include <string>

#include "ui/tabs/tab.h"

namespace lmc::ui::testing {

class LastStatus final : public StatusSink {
 public:
  void set_status(const std::string& text, bool is_error) override {
    last = text;
    error = is_error;
  }
  std::string last;
  bool error = false;
};

}  // namespace lmc::ui::testing
