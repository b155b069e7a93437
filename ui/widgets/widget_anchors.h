#pragma once
// Named screen rectangles of a panel's important controls (Start, Cancel, Apply ...), recorded as
// they are drawn. Headless panel tests click them by name instead of guessing pixel positions,
// which keeps the tests readable and robust to layout changes.
#include <imgui.h>

#include <map>
#include <optional>
#include <string>

namespace lmc::ui {

class WidgetAnchors {
 public:
  // Records the last submitted item's rectangle under `name`, with the rectangle the window clips
  // it to (so a test can tell a label that runs off the panel from one that fits).
  void remember(const std::string& name) {
    const ImDrawList* list = ImGui::GetWindowDrawList();
    rects_[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), list->GetClipRectMin(), list->GetClipRectMax()};
  }
  void clear() { rects_.clear(); }
  std::optional<ImVec2> centre(const std::string& name) const {
    const auto it = rects_.find(name);
    if (it == rects_.end()) return std::nullopt;
    return ImVec2((it->second.min.x + it->second.max.x) * 0.5f, (it->second.min.y + it->second.max.y) * 0.5f);
  }
  // The item ends inside the window's visible width (a scrolling window may still hide it above
  // or below); false when it was not drawn.
  bool fits_across(const std::string& name) const {
    const auto it = rects_.find(name);
    return it != rects_.end() && it->second.min.x >= it->second.clip_min.x - 0.5f &&
           it->second.max.x <= it->second.clip_max.x + 0.5f;
  }
  // The whole item is inside the window's visible rectangle.
  bool fully_visible(const std::string& name) const {
    const auto it = rects_.find(name);
    return fits_across(name) && it->second.min.y >= it->second.clip_min.y - 0.5f &&
           it->second.max.y <= it->second.clip_max.y + 0.5f;
  }

 private:
  struct Rects {
    ImVec2 min, max;            // the item
    ImVec2 clip_min, clip_max;  // what its window shows
  };
  std::map<std::string, Rects> rects_;
};

}  // namespace lmc::ui
