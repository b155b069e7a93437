#include "ui/tabs/review/review_replay_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/model/review/replay_frame.h"
#include "ui/widgets/live_hands_view.h"

namespace lmc::ui {

void ReviewReplayPanel::draw() {
  anchors_.clear();  // only what this frame drew
  const ReviewState& state = *state_;
  const auto view = state.view();
  if (!view || !view->result || view->series.time_s.empty()) return;
  LinkedXRange& range = *state.x_range();
  const double t0 = view->series.time_s.front(), t1 = view->series.time_s.back();
  double t = range.cursor.value_or(range.lo());
  if (playing_) {
    t += ImGui::GetIO().DeltaTime;  // real time
    if (t >= t1) {
      t = t1;
      playing_ = false;
    }
    range.cursor = t;
  }
  if (ImGui::Button(playing_ ? "Pause" : "Play", ImVec2(56, 0))) {
    if (!playing_ && t >= t1) t = t0;  // play again from the start
    playing_ = !playing_;
    range.cursor = t;
  }
  anchors_.remember("play");
  ImGui::SameLine();
  float slider = static_cast<float>(std::clamp(t, t0, t1));
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderFloat("##time", &slider, static_cast<float>(t0), static_cast<float>(t1), "%.2f s")) {
    range.cursor = slider;
    playing_ = false;
  }
  anchors_.remember("time");
  const auto frame = replay_frame(*view->result, std::clamp(t, t0, t1));
  if (!frame) return;
  char caption[160];
  std::snprintf(caption, sizeof caption,
                "%.2f s: controllers in their slot colours, Vicon light grey, the fused hand by how many controllers "
                "see each finger",
                frame->t_s);
  draw_live_hands_view("replay", camera_, view->layout, frame->hands, caption, frame->fused ? &*frame->fused : nullptr);
}

}  // namespace lmc::ui
