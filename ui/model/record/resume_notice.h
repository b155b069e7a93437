#pragma once
// The plain notice an operator reads first when a session folder is opened again:
// which trials were cut off while recording and what happens to their rows, how far the session
// got, and where it continues. Built from the folder's state, so the Record tab and its tests
// read the same words.
#include <string>
#include <vector>

#include "core/session/session_state.h"

namespace lmc::ui {

// `recovered`: the trials SessionFolder::open found recording when their program stopped.
std::vector<std::string> resume_notice(const SessionState& state, const std::vector<std::string>& recovered);

}  // namespace lmc::ui
