#pragma once
// The manifest (`session.json`) as text, rewritten after every journal event. Serialising every
// trial's verdict again for each event would make a session's bookkeeping quadratic in its length
// (the manifest is rewritten hundreds of times and grows to hundreds of kilobytes), so each trial's
// entry is kept as text and only the entry the event changed is serialised again
// (trial_changed_by). The text is byte for byte
// session_manifest_json(state).dump(2), which stays the one definition of the document.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/session/session_state.h"

namespace lmc {

class ManifestText {
 public:
  // The manifest of `state`, right after `changed_trial` (trial_changed_by of the event just
  // applied) changed; kAllTrialsChanged when unknown.
  std::string render(const SessionState& state, int changed_trial);

 private:
  std::vector<std::string> trial_text_;  // entries indented for their place in the "trials" array
  std::vector<bool> fresh_;
};

}  // namespace lmc
