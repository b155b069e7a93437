#include "ui/model/shell/status_board.h"

namespace lmc::ui {

void StatusBoard::post(const std::string& tab_id, const std::string& text, bool is_error) {
  latest_[tab_id] = StatusLine{text, is_error, false, next_sequence_++};
}

std::optional<StatusLine> StatusBoard::latest(const std::string& tab_id) const {
  const auto it = latest_.find(tab_id);
  if (it == latest_.end()) return std::nullopt;
  return it->second;
}

StatusLine StatusBoard::shown(const std::string& tab_id) const {
  const auto own = latest(tab_id);
  if (own && own->is_error) return *own;
  if (hint_showing()) return StatusLine{hint_, false, true, 0};
  if (own) return *own;
  return StatusLine{idle_, false, false, 0};
}

}  // namespace lmc::ui
