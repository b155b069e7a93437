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
  // Records the last submitted item's rectangle under `name`.
  void remember(const std::string& name) { rects_[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()}; }
  void clear() { rects_.clear(); }
  std::optional<ImVec2> centre(const std::string& name) const {
    const auto it = rects_.find(name);
    if (it == rects_.end()) return std::nullopt;
    return ImVec2((it->second.first.x + it->second.second.x) * 0.5f, (it->second.first.y + it->second.second.y) * 0.5f);
  }

 private:
  std::map<std::string, std::pair<ImVec2, ImVec2>> rects_;
};

}  // namespace lmc::ui
