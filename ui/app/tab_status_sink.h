#pragma once
// The StatusSink the shell gives one tab: whatever the tab says is filed under its id, so the
// status bar can show each tab its own messages (ui/model/shell/status_board.h).
#include <string>
#include <utility>

#include "ui/model/shell/status_board.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

class TabStatusSink final : public StatusSink {
 public:
  TabStatusSink(StatusBoard& board, std::string tab_id) : board_(board), tab_id_(std::move(tab_id)) {}
  void set_status(const std::string& text, bool is_error) override { board_.post(tab_id_, text, is_error); }

 private:
  StatusBoard& board_;
  std::string tab_id_;
};

}  // namespace lmc::ui
