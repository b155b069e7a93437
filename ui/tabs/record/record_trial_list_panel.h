#pragma once
// The whole protocol as a list: grouped by layout block, one row per trial with its
// status (pending, recording, pass, warn, fail, interrupted, accepted) and attempt count. Returns
// the trial clicked this frame (-1: none).
#include "core/session/session_state.h"

namespace lmc::ui {

int draw_record_trial_list(const session::SessionState& state, int current, int recording);

}  // namespace lmc::ui
