#include "ui/tabs/layout/scene_panel.h"

#include <imgui_internal.h>  // SetItemUsingMouseWheel (1.86 keeps it internal)

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/hand/hand_frame.h"
#include "ui/scene/colour_maps.h"
#include "ui/scene/device_case.h"
#include "ui/scene/label_spreading.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

double point_segment_px(const ImVec2& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d q(p.x, p.y), ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 1e-9 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (q - (a + t * ab)).norm();
}

const char* verb_for(HandleKind k) {
  switch (k) {
    case HandleKind::kYaw:
      return "Rotate";
    case HandleKind::kTilt:
      return "Tilt";
    default:
      return "Move";
  }
}

constexpr const char* kFingerLegendTitle = "Fingers:";

}  // namespace

ScenePanel::ScenePanel(std::shared_ptr<LayoutState> state, std::function<SceneRenderer*()> renderer)
    : Panel("##scene"), state_(std::move(state)), renderer_(std::move(renderer)) {}

void ScenePanel::frame_all() {
  frame_requested_ = true;
}

Ray ScenePanel::mouse_ray() const {
  const ImVec2 m = ImGui::GetIO().MousePos;
  return state_->camera.ray_through_pixel(m.x - image_min_.x, m.y - image_min_.y, image_size_.x, image_size_.y);
}

int ScenePanel::pick_device(const Ray& ray) const {
  int best = -1;
  double best_t = 1e300;
  const Layout& l = state_->layout();
  for (int i = 0; i < l.device_count(); ++i) {
    const LayoutDevice& d = l.devices[static_cast<size_t>(i)];
    Eigen::Isometry3d t = d.pose.device_to_world();
    t.translation() += d.offset_mm;
    // A slightly larger box than drawn: a case 10-12 mm high is thin to hit from the side.
    const DeviceCaseBox case_box = device_case_box(d);
    if (const auto hit =
            intersect_oriented_box(ray, t, case_box.centre_mm, case_box.half_mm + Eigen::Vector3d(4, 4, 4))) {
      if (*hit < best_t) {
        best_t = *hit;
        best = i;
      }
    }
  }
  return best;
}

// What is under the pointer (only while no gesture runs): a handle of the selected controller,
// else a controller.
void ScenePanel::update_hover(bool hovered, ImVec2 m) {
  if (gesture_ != Gesture::kNone) return;
  LayoutState& s = *state_;
  s.set_hover(-1, HandleKind::kNone);
  if (!hovered) return;
  if (s.selected() >= 0 && s.selected() < s.doc().device_count()) {
    const HandleHit hit = hover_handle(s.layout().devices[static_cast<size_t>(s.selected())],
                                       s.doc().locks[static_cast<size_t>(s.selected())], s.camera, m.x, m.y,
                                       image_size_.x, image_size_.y);
    if (hit.kind != HandleKind::kNone) s.set_hover(s.selected(), hit.kind);
  }
  if (s.hovered_handle() == HandleKind::kNone) s.set_hover(pick_device(mouse_ray()), HandleKind::kNone);
}

// A press starts a gesture: on a handle or a controller a drag (which selects it), elsewhere
// (or on a locked controller) an orbit; the right or middle button pans.
void ScenePanel::begin_gesture(bool hovered) {
  if (gesture_ != Gesture::kNone || !hovered) return;
  LayoutState& s = *state_;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) gesture_ = Gesture::kPan;
  }
  if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
  press_pos_ = ImGui::GetIO().MousePos;
  moved_ = false;
  HandleKind kind = s.hovered_handle();
  const int device = s.hovered();
  if (kind == HandleKind::kNone && device >= 0) {
    s.select(device);
    kind = HandleKind::kMove;
  }
  gesture_ = Gesture::kOrbit;  // empty space, or a locked controller: the press only selects
  if (device < 0) return;
  s.upd_history().rollback();
  if (drag_.begin(kind, s.layout().devices[static_cast<size_t>(device)], s.doc().locks[static_cast<size_t>(device)],
                  mouse_ray())) {
    gesture_ = Gesture::kHandle;
    drag_device_ = device;
    s.set_active_handle(kind);
  }
}

// A handle drag: previews while the button is down, commits as one undo step on release; Escape
// puts the controller back.
void ScenePanel::continue_drag(float moved_px) {
  LayoutState& s = *state_;
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    cancel_preview(s.upd_history());
    drag_.end();
    gesture_ = Gesture::kNone;
    s.set_active_handle(HandleKind::kNone);
    s.set_status("Drag cancelled");
    return;
  }
  if (ImGui::GetIO().MouseDown[ImGuiMouseButton_Left]) {
    if (moved_px > 2.0f) moved_ = true;
    if (moved_) {
      if (const auto pose = drag_.update(mouse_ray())) preview_device_pose(s.upd_history(), drag_device_, *pose);
    }
    return;
  }
  if (commit_device_pose(s.upd_history(), drag_device_, verb_for(drag_.kind()))) {
    s.set_status(s.history().undo_message() + " (Ctrl+Z to undo)");
  } else {
    s.upd_history().rollback();
  }
  drag_.end();
  gesture_ = Gesture::kNone;
  s.set_active_handle(HandleKind::kNone);
}

void ScenePanel::handle_input(bool hovered) {
  LayoutState& s = *state_;
  ImGuiIO& io = ImGui::GetIO();
  const double w = image_size_.x, h = image_size_.y;
  const ImVec2 m(io.MousePos.x - image_min_.x, io.MousePos.y - image_min_.y);
  update_hover(hovered, m);
  begin_gesture(hovered);
  const float moved_px = std::abs(io.MousePos.x - press_pos_.x) + std::abs(io.MousePos.y - press_pos_.y);
  switch (gesture_) {
    case Gesture::kHandle:
      continue_drag(moved_px);
      break;
    case Gesture::kOrbit:
      if (io.MouseDown[ImGuiMouseButton_Left]) {
        if (moved_px > 3.0f) moved_ = true;
        if (moved_) s.camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
      } else {
        if (!moved_ && s.hovered() < 0) s.select(-1);  // a click on empty space clears the selection
        gesture_ = Gesture::kNone;
      }
      break;
    case Gesture::kPan:
      if (io.MouseDown[ImGuiMouseButton_Right] || io.MouseDown[ImGuiMouseButton_Middle]) {
        s.camera.pan(io.MouseDelta.x, io.MouseDelta.y, h);
      } else {
        gesture_ = Gesture::kNone;
      }
      break;
    case Gesture::kNone:
      break;
  }
  if (hovered && io.MouseWheel != 0.0f) s.camera.zoom_towards(m.x, m.y, w, h, io.MouseWheel);
}

void ScenePanel::draw(ImVec2 size) {
  LayoutState& s = *state_;
  image_min_ = ImGui::GetCursorScreenPos();
  image_size_ = ImVec2(std::max(size.x, 16.0f), std::max(size.y, 16.0f));
  if (frame_requested_) {
    frame_requested_ = false;
    SceneInputs in;
    in.layout = &s.layout();
    in.hand = s.current_hand();
    const SceneList probe = build_scene(in);
    // Frame the controllers and the hand, and enough of the table to read its grid around them.
    Eigen::Vector3d lo = probe.bounds_lo.cwiseMin(Eigen::Vector3d(-300, 0, -300));
    Eigen::Vector3d hi = probe.bounds_hi.cwiseMax(Eigen::Vector3d(300, 0, 300));
    s.camera.frame_bounds(lo, hi, image_size_.x / image_size_.y);
  }

  ImGui::InvisibleButton(
      "##scene", image_size_,
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  // The wheel zooms the view; without this ImGui also hands it to the tab's window, which then
  // scrolled by its 2 px of overflow.
  ImGui::SetItemUsingMouseWheel();
  const bool hovered = ImGui::IsItemHovered();
  handle_input(hovered);

  // Build after input so the picture shows this frame's edit.
  SceneInputs in;
  in.layout = &s.layout();
  in.locks = &s.doc().locks;
  in.selected = s.selected();
  in.hovered = s.hovered();
  in.hovered_handle = s.hovered_handle();
  in.active_handle = s.active_handle();
  in.hand = s.current_hand();
  in.finger_seen_count = s.frame_visibility().seen_count;
  in.show_pyramids = s.display.show_pyramids;
  in.table_half_extent_mm = std::max(400.0, s.display.heatmap_half_extent_mm);
  if (s.display.show_rays && s.selected() >= 0) in.rays = &s.frame_visibility().rays;
  const std::array<double, 4> search_box = {s.doc().bounds.range[0].lo, s.doc().bounds.range[0].hi,
                                            s.doc().bounds.range[2].lo, s.doc().bounds.range[2].hi};
  if (s.display.show_search_box) in.search_box = &search_box;
  HeatmapGridPtr grid;
  if (s.display.show_heatmap && s.selected() >= 0) {
    grid = s.heatmap().latest();
    if (grid && grid->device == s.selected()) {
      in.heatmap = grid.get();
      in.heatmap_range = s.heatmap_range();
    }
  }
  const std::shared_ptr<const Layout> ghost = s.optimiser().best_so_far();
  if (s.display.show_ghost && ghost) in.ghost = ghost.get();
  scene_ = build_scene(in);

  SceneRenderer* r = renderer_ ? renderer_() : nullptr;
  const std::uintptr_t tex =
      r ? r->render(scene_, s.camera, static_cast<int>(image_size_.x), static_cast<int>(image_size_.y)) : 0;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 image_max(image_min_.x + image_size_.x, image_min_.y + image_size_.y);
  if (tex != 0) {
    dl->AddImage(reinterpret_cast<ImTextureID>(tex), image_min_, image_max, ImVec2(0, 1), ImVec2(1, 0));
  } else {
    dl->AddRectFilled(image_min_, image_max, palette::kSceneBackground);
  }
  draw_overlays(dl);
}

// Where the overlays stand on the view: the finger legend (bottom left), the heatmap's colour bar
// (bottom right, while the heatmap shows) and the bar's heading.
struct ScenePanel::OverlayPlaces {
  ImVec2 image_max;
  float line = 0;
  ImVec2 legend_at;  // the legend's first text
  float legend_w = 0;
  bool heat_bar = false;
  float bar_w = 0;
  std::string heading;  // "frames visible, all fingers (preview)"
  ImRect legend_box, bar_box;
};

ScenePanel::OverlayPlaces ScenePanel::place_overlays() const {
  const LayoutState& s = *state_;
  OverlayPlaces o;
  o.image_max = ImVec2(image_min_.x + image_size_.x, image_min_.y + image_size_.y);
  o.line = ImGui::GetTextLineHeight();
  // Legend: finger colours (categorical, every category listed).
  o.legend_w = ImGui::CalcTextSize(kFingerLegendTitle).x + 10;
  for (int c = 0; c < kSeenCountCategories; ++c)
    o.legend_w += o.line + 2 + ImGui::CalcTextSize(seen_count_label(c).c_str()).x + 12;
  o.legend_at = ImVec2(image_min_.x + 10, o.image_max.y - 10 - o.line * 1.6f);
  // The heatmap's colour bar (bottom right) is at least 220 px wide and as wide as its heading, so
  // that "frames visible, all fingers (preview)" is never cut at the scene's edge.
  o.heat_bar = s.display.show_heatmap && s.selected() >= 0;
  if (o.heat_bar) {
    const HeatmapGridPtr grid = s.heatmap().latest();
    const std::string finger =
        s.display.heatmap_finger < 0 ? std::string("all fingers") : std::string(digit_name(s.display.heatmap_finger));
    char head[128];
    std::snprintf(head, sizeof head, "%s, %s%s",
                  s.display.heatmap_mode == HeatmapMode::kShareVisible ? "frames visible" : "frames added",
                  finger.c_str(), (grid && !grid->fine) ? " (preview)" : "");
    o.heading = head;
  }
  o.bar_w = std::max(220.0f, ImGui::CalcTextSize(o.heading.c_str()).x);
  // In a narrow scene the colour bar would cover the finger legend: stack the finger legend above
  // it instead.
  if (o.heat_bar && o.legend_at.x + o.legend_w > o.image_max.x - o.bar_w - 16 - 8) o.legend_at.y -= o.line * 3.6f + 28;
  const ImVec2 at = o.legend_at;
  o.legend_box = ImRect(ImVec2(at.x - 6, at.y - 6), ImVec2(at.x + o.legend_w, at.y + o.line + 6));
  if (o.heat_bar) {
    o.bar_box = ImRect(ImVec2(o.image_max.x - o.bar_w - 24, o.image_max.y - 14 - o.line * 3.6f - 10),
                       ImVec2(o.image_max.x - 6, o.image_max.y - 6));
  }
  return o;
}

// Labels at projected positions, spread so none prints over another, with a shadow so they read on
// any background; kept inside the view (moved in from its edge) and off the legend and the colour
// bar, which would cover them.
void ScenePanel::draw_labels(ImDrawList* dl, const OverlayPlaces& o) const {
  const double w = image_size_.x, h = image_size_.y;
  // The view as the window shows it (its right edge may lie under the window's padding).
  const ImVec2 clip_min = dl->GetClipRectMin(), clip_max = dl->GetClipRectMax();
  std::vector<const SceneLabel*> shown;
  std::vector<LabelBox> boxes;
  for (const SceneLabel& l : scene_.labels) {
    const auto p = state_->camera.project(l.position, w, h);
    if (!p) continue;
    const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
    shown.push_back(&l);
    // The box holds the text and the 3 px backing an emphasised label gets on either side.
    boxes.push_back({image_min_.x + static_cast<float>(p->x()) - size.x * 0.5f - 3.0f,
                     image_min_.y + static_cast<float>(p->y()) - size.y * 0.5f - 1.0f, size.x + 6.0f, size.y + 2.0f});
  }
  boxes = spread_labels(std::move(boxes), 1.0f);
  for (size_t i = 0; i < shown.size(); ++i) {
    const SceneLabel& l = *shown[i];
    const ImVec2 size(boxes[i].width - 6.0f, boxes[i].height - 2.0f);
    // Its shadow reaches a pixel further right and down.
    const ImVec2 pos(std::clamp(boxes[i].x + 3.0f, clip_min.x, std::max(clip_min.x, clip_max.x - size.x - 2.0f)),
                     std::clamp(boxes[i].y + 1.0f, clip_min.y, std::max(clip_min.y, clip_max.y - size.y - 2.0f)));
    const ImRect text_box(pos, ImVec2(pos.x + size.x + 1.0f, pos.y + size.y + 1.0f));
    if (text_box.Overlaps(o.legend_box) || (o.heat_bar && text_box.Overlaps(o.bar_box))) continue;
    if (l.emphasised) {
      dl->AddRectFilled(ImVec2(pos.x - 3, pos.y - 1), ImVec2(pos.x + size.x + 3, pos.y + size.y + 1),
                        palette::kLabelBackground, 3.0f);
    }
    dl->AddText(ImVec2(pos.x + 1, pos.y + 1), palette::kTextShadow, l.text.c_str());
    dl->AddText(pos, to_u32(l.colour), l.text.c_str());
  }
}

void ScenePanel::draw_finger_legend(ImDrawList* dl, const OverlayPlaces& o) {
  const ImVec2 at = o.legend_at;
  const float line = o.line;
  dl->AddRectFilled(ImVec2(at.x - 6, at.y - 6), ImVec2(at.x + o.legend_w, at.y + line + 6), palette::kOverlayBackground,
                    4.0f);
  dl->AddText(at, palette::kOverlayText, kFingerLegendTitle);
  float x = at.x + ImGui::CalcTextSize(kFingerLegendTitle).x + 10;
  for (int c = 0; c < kSeenCountCategories; ++c) {
    dl->AddRectFilled(ImVec2(x, at.y + 1), ImVec2(x + line - 2, at.y + line - 1), to_u32(seen_count_colour(c)), 2.0f);
    x += line + 2;
    const std::string label = seen_count_label(c);
    dl->AddText(ImVec2(x, at.y), palette::kOverlayText, label.c_str());
    x += ImGui::CalcTextSize(label.c_str()).x + 12;
  }
}

// The heatmap's colour bar (magnitude: a sequential map with numbers).
void ScenePanel::draw_heat_bar(ImDrawList* dl, const OverlayPlaces& o) const {
  const float line = o.line;
  const float bw = o.bar_w, bx = o.image_max.x - bw - 16, by = o.image_max.y - 14 - line * 2.6f;
  dl->AddRectFilled(ImVec2(bx - 8, by - line - 10), ImVec2(o.image_max.x - 6, o.image_max.y - 6),
                    palette::kOverlayBackground, 4.0f);
  dl->AddText(ImVec2(bx, by - line - 4), palette::kOverlayText, o.heading.c_str());
  const ColourRange range = state_->heatmap_range();
  constexpr int kSteps = 44;
  for (int i = 0; i < kSteps; ++i) {
    const float x0 = bx + bw * i / kSteps, x1 = bx + bw * (i + 1) / kSteps + 0.5f;
    const ImU32 a = to_u32(viridis(static_cast<double>(i) / kSteps)),
                b = to_u32(viridis(static_cast<double>(i + 1) / kSteps));
    dl->AddRectFilledMultiColor(ImVec2(x0, by), ImVec2(x1, by + line * 0.8f), a, b, b, a);
  }
  char lo[24], mid[24], hi[24];
  std::snprintf(lo, sizeof lo, "%.0f %%", range.lo * 100);
  std::snprintf(mid, sizeof mid, "%.0f %%", 0.5 * (range.lo + range.hi) * 100);
  std::snprintf(hi, sizeof hi, "%.0f %%", range.hi * 100);
  const float ty = by + line * 0.9f;
  dl->AddText(ImVec2(bx, ty), palette::kOverlayTickText, lo);
  dl->AddText(ImVec2(bx + bw * 0.5f - ImGui::CalcTextSize(mid).x * 0.5f, ty), palette::kOverlayTickText, mid);
  dl->AddText(ImVec2(bx + bw - ImGui::CalcTextSize(hi).x, ty), palette::kOverlayTickText, hi);
}

// A ray's verdict, else the controller under the cursor.
void ScenePanel::draw_tooltips() const {
  if (gesture_ != Gesture::kNone || !ImGui::IsItemHovered()) return;
  const LayoutState& s = *state_;
  const double w = image_size_.x, h = image_size_.y;
  const ImVec2 m(ImGui::GetIO().MousePos.x - image_min_.x, ImGui::GetIO().MousePos.y - image_min_.y);
  if (s.display.show_rays && s.selected() >= 0 && s.hovered() < 0) {
    const auto& rays = s.frame_visibility().rays;
    double best = 6.0;
    int best_i = -1;
    for (size_t i = 0; i < rays.size(); ++i) {
      const auto a = s.camera.project(rays[i].from, w, h), b = s.camera.project(rays[i].to, w, h);
      if (!a || !b) continue;
      const double d = point_segment_px(m, *a, *b);
      if (d < best) {
        best = d;
        best_i = static_cast<int>(i);
      }
    }
    if (best_i >= 0) {
      const FingerRay& r = rays[static_cast<size_t>(best_i)];
      ImGui::SetTooltip("%s -> %s\n%s", s.layout().devices[static_cast<size_t>(s.selected())].slot.c_str(),
                        hand_point_words(r.marker).c_str(), r.reason.c_str());
      return;
    }
  }
  if (s.hovered() >= 0 && s.hovered() < s.layout().device_count()) {
    const LayoutDevice& d = s.layout().devices[static_cast<size_t>(s.hovered())];
    const char* hint = s.hovered_handle() == HandleKind::kYaw    ? "drag the green ring to turn (ry)"
                       : s.hovered_handle() == HandleKind::kTilt ? "drag the red ring to tilt (rx)"
                                                                 : "drag to move on the table";
    ImGui::SetTooltip("%s\nx %.1f  z %.1f mm · rx %.1f° ry %.1f°\n%s", d.slot.c_str(), d.pose.x_mm, d.pose.z_mm,
                      d.pose.rx_deg, d.pose.ry_deg, hint);
  }
}

void ScenePanel::draw_overlays(ImDrawList* dl) {
  const OverlayPlaces o = place_overlays();
  dl->PushClipRect(image_min_, o.image_max, true);
  draw_labels(dl, o);
  draw_finger_legend(dl, o);
  if (o.heat_bar) draw_heat_bar(dl, o);
  dl->PopClipRect();
  draw_tooltips();
}

}  // namespace lmc::ui
