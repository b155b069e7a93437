#include "ui/tabs/record/record_note_panel.h"

#include <string>

namespace lmc::ui {

void RecordNotePanel::reset() {
  text_[0] = '\0';
  open_ = focus_ = took_keyboard_ = submit_when_typed_ = false;
  held_.clear();
  opened_frame_ = -1;
  opened_time_ = 0.0;
}

void RecordNotePanel::open(bool by_key) {
  if (open_) {
    focus_ = !took_keyboard_;
    return;
  }
  reset();
  open_ = true;
  focus_ = true;
  opened_frame_ = ImGui::GetFrameCount();
  opened_time_ = ImGui::GetTime();
  if (by_key) {
    // A fast typist's first letters can arrive in the same frame as the N: keep what follows it.
    const ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    bool after_n = false;
    for (ImWchar c : queue) {
      if (after_n)
        held_.push_back(c);
      else
        after_n = c == 'n' || c == 'N';
    }
  }
}

bool RecordNotePanel::draw() {
  const RecordState& model = *model_;
  bool submitted = false;
  if (open_) {
    if (focus_) {
      ImGui::SetKeyboardFocusHere();
      focus_ = false;
    }
    // Characters typed after N but before the field has the keyboard (the N's own 'n' arrives in
    // the frame that opened the line and is left out); an Enter or Esc among them is kept too.
    const bool early = !took_keyboard_ && ImGui::GetFrameCount() > opened_frame_;
    ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    if (early) {
      held_.insert(held_.end(), queue.begin(), queue.end());
      queue.resize(0);
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) submit_when_typed_ = true;
    } else if (took_keyboard_ && !held_.empty()) {
      ImVector<ImWchar> typed;
      for (ImWchar c : held_) typed.push_back(c);
      for (ImWchar c : queue) typed.push_back(c);
      queue.swap(typed);
      held_.clear();
    }
    ImGui::PushItemWidth(420);
    const int target = model.note_trial();
    const std::string hint =
        "note on " +
        (target >= 0 ? model.state().trials.at(static_cast<size_t>(target)).plan.name : std::string("the trial")) +
        ": Enter keeps it, Esc drops it";
    const bool enter =
        ImGui::InputTextWithHint("##note", hint.c_str(), text_, sizeof text_, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool active = ImGui::IsItemActive();
    const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    if (active) took_keyboard_ = true;
    if (enter) {
      // An Enter in the very frame the field took the keyboard, with held letters not yet typed
      // into it, waits for them.
      if (held_.empty())
        submitted = true;
      else
        submit_when_typed_ = true;
    } else if (submit_when_typed_ && took_keyboard_ && held_.empty()) {
      submitted = true;
      submit_when_typed_ = false;
    }
    if (escape && (active || ImGui::IsItemDeactivated() || early)) {
      reset();
    }
    ImGui::PopItemWidth();
  }
  return submitted;
}

}  // namespace lmc::ui
