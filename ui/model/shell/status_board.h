#pragma once
// The status bar's messages, kept per tab: a layout error must not stay red on the Devices tab.
// Each tab posts under its own id; the shell shows the active tab's latest message. Before the
// user's first action the shell shows a one-line hint for a newcomer instead of a tab's routine
// message (an error still wins: it may explain why the hint would not work).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace lmc::ui {

struct StatusLine {
  std::string text;
  bool is_error = false;
  bool is_hint = false;        // the newcomer's hint, drawn dimmed
  std::uint64_t sequence = 0;  // order of posting across tabs (0 = nothing posted)
};

class StatusBoard {
 public:
  explicit StatusBoard(std::string newcomer_hint = {}, std::string idle_text = "Ready.")
      : hint_(std::move(newcomer_hint)), idle_(std::move(idle_text)) {}

  void post(const std::string& tab_id, const std::string& text, bool is_error);
  // The tab's latest message, if it posted one.
  std::optional<StatusLine> latest(const std::string& tab_id) const;
  // What the status bar shows while `tab_id` is the active tab.
  StatusLine shown(const std::string& tab_id) const;

  // The user acted (clicked, pressed a key): the newcomer's hint is no longer needed.
  void dismiss_hint() { hint_dismissed_ = true; }
  bool hint_showing() const { return !hint_dismissed_ && !hint_.empty(); }

 private:
  std::map<std::string, StatusLine> latest_;
  std::uint64_t next_sequence_ = 1;
  std::string hint_;
  std::string idle_;
  bool hint_dismissed_ = false;
};

}  // namespace lmc::ui
