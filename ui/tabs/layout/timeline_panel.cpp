#include "ui/tabs/layout/timeline_panel.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "core/hand/reference_poses.h"

namespace lmc::ui {
namespace {

// The filters, the speed and the count beside the slider; the slider wants this much at least to
// show most descriptions ("frame 12: horizontal palm, index at 40 %").
constexpr float kFiltersWidth = 470.0f;
constexpr float kSliderWants = 250.0f;

bool two_rows(float width) {
  return width - 56.0f - ImGui::GetStyle().ItemSpacing.x - kFiltersWidth < kSliderWants;
}

}  // namespace

float TimelinePanel::height(float width) const {
  return two_rows(width) ? ImGui::GetFrameHeight() * 2 + ImGui::GetStyle().ItemSpacing.y
                         : ImGui::GetFrameHeightWithSpacing();
}

void TimelinePanel::draw() {
  LayoutState& s = *state_;
  TimelineState& t = s.timeline;
  const PoseSetPtr p = s.poses.current();
  const auto& frames = s.timeline_frames();

  if (ImGui::Button(t.playing ? "Pause" : "Play", ImVec2(56, 0))) t.playing = !t.playing;
  ImGui::SameLine();
  int pos = 0;
  if (!frames.empty()) {
    pos = static_cast<int>(std::lower_bound(frames.begin(), frames.end(), t.frame) - frames.begin());
    pos = std::clamp(pos, 0, static_cast<int>(frames.size()) - 1);
  }
  const bool wrapped =
      two_rows(ImGui::GetContentRegionAvail().x + ImGui::GetItemRectSize().x + ImGui::GetStyle().ItemSpacing.x);
  ImGui::SetNextItemWidth(wrapped ? -1.0f : ImGui::GetContentRegionAvail().x - kFiltersWidth);
  const int max_pos = std::max(0, static_cast<int>(frames.size()) - 1);
  char overlay[128] = "loading pose set...";
  if (p && !frames.empty()) {
    const PoseLabel& l = p->set.labels[static_cast<size_t>(t.frame)];
    // Words rather than the pose set's "horizontal/thumb" keys.
    const std::string palm(orientation_words(l.orientation)), motion(motion_words(l.motion));
    if (l.motion == HandMotion::kOpen) {
      std::snprintf(overlay, sizeof overlay, "frame %d: %s, %s", t.frame, palm.c_str(), motion.c_str());
    } else {
      std::snprintf(overlay, sizeof overlay, "frame %d: %s, %s at %.0f %%", t.frame, palm.c_str(), motion.c_str(),
                    l.progress * 100.0);
    }
  } else if (p) {
    std::snprintf(overlay, sizeof overlay, "no frames match the filters");
  }
  if (ImGui::SliderInt("##frame", &pos, 0, max_pos, overlay) && !frames.empty()) {
    t.frame = frames[static_cast<size_t>(pos)];
    t.playing = false;
  }
  if (!wrapped) ImGui::SameLine();
  const char* orientations[] = {"any palm", "horizontal", "vertical"};
  int o = t.orientation_filter + 1;
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("##orientation", &o, orientations, 3)) t.orientation_filter = o - 1;
  ImGui::SameLine();
  const char* motions[] = {"any motion", "open", "index", "thumb", "wrist flexion", "wrist extension"};
  int mo = t.motion_filter + 1;
  ImGui::SetNextItemWidth(130);
  if (ImGui::Combo("##motion", &mo, motions, 6)) t.motion_filter = mo - 1;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  float fps = static_cast<float>(t.frames_per_second);
  if (ImGui::DragFloat("##fps", &fps, 0.5f, 1.0f, 240.0f, "%.0f fps")) t.frames_per_second = fps;
  ImGui::SameLine();
  ImGui::TextDisabled("%zu of %d", frames.size(), p ? p->size() : 0);
}

}  // namespace lmc::ui
