#include "core/session/manifest_text.h"

namespace lmc {
namespace {

// A stand-in for the trials array that the serialiser writes as one string on the "trials" line.
// It cannot be a trial's text: control characters are written escaped ("\u0001").
constexpr const char* kTrialsPlaceholder = "\x01trials\x01";

// An entry of the root object's "trials" array sits two levels deep: dump(2) of the entry alone,
// every line indented by four spaces. Strings never hold a raw line break in dump's output, so
// every line break is the serialiser's own.
std::string indented_entry(const nlohmann::json& entry) {
  const std::string text = entry.dump(2);
  std::string out = "    ";
  out.reserve(text.size() + text.size() / 8);
  for (const char c : text) {
    out += c;
    if (c == '\n') out += "    ";
  }
  return out;
}

}  // namespace

std::string ManifestText::render(const SessionState& state, int changed_trial) {
  const size_t n = state.trials.size();
  if (trial_text_.size() != n || changed_trial == kAllTrialsChanged) {
    trial_text_.assign(n, std::string());
    fresh_.assign(n, false);
  } else if (changed_trial >= 0 && static_cast<size_t>(changed_trial) < n) {
    fresh_[static_cast<size_t>(changed_trial)] = false;
  }
  for (size_t i = 0; i < n; ++i) {
    if (fresh_[i]) continue;
    trial_text_[i] = indented_entry(manifest_trial_json(state, state.trials[i]));
    fresh_[i] = true;
  }
  nlohmann::json root = manifest_json_without_trials(state);
  root["trials"] = kTrialsPlaceholder;
  std::string text = root.dump(2);
  const std::string placeholder = nlohmann::json(kTrialsPlaceholder).dump();
  std::string trials;
  if (n == 0) {
    trials = "[]";
  } else {
    size_t size = 8;
    for (const auto& t : trial_text_) size += t.size() + 2;
    trials.reserve(size);
    trials = "[\n";
    for (size_t i = 0; i < n; ++i) {
      trials += trial_text_[i];
      trials += i + 1 < n ? ",\n" : "\n";
    }
    trials += "  ]";
  }
  text.replace(text.find(placeholder), placeholder.size(), trials);
  return text;
}

}  // namespace lmc
