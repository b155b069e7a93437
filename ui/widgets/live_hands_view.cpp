#include "ui/widgets/live_hands_view.h"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "ui/scene/colour_maps.h"
#include "ui/scene/label_spreading.h"
#include "ui/scene/scene_items.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {

namespace {

struct SlotLabel {
  Eigen::Vector2d at;  // projected anchor, pixels
  ImU32 colour;
  std::string text;
};

// The view's canvas: world points projected through the camera into it, lines drawn on it.
class Canvas {
 public:
  Canvas(ImDrawList* dl, const OrbitCamera& camera, ImVec2 origin, ImVec2 size)
      : dl_(dl), camera_(camera), origin_(origin), size_(size) {}

  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& w) const {
    auto p = camera_.project(w, size_.x, size_.y);
    if (p) *p += Eigen::Vector2d(origin_.x, origin_.y);
    return p;
  }
  void line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, ImU32 col, float thickness) const {
    auto pa = project(a);
    auto pb = project(b);
    if (pa && pb)
      dl_->AddLine(ImVec2(static_cast<float>(pa->x()), static_cast<float>(pa->y())),
                   ImVec2(static_cast<float>(pb->x()), static_cast<float>(pb->y())), col, thickness);
  }
  ImDrawList* draw_list() const { return dl_; }

 private:
  ImDrawList* dl_;
  const OrbitCamera& camera_;
  ImVec2 origin_, size_;
};

// The table top (y = 0), 50 mm grid, world axes at the origin.
void draw_table_and_axes(const Canvas& v) {
  for (int k = -300; k <= 300; k += 50) {
    const ImU32 col = k == 0 ? palette::kGridCentre : palette::kGrid;
    v.line({static_cast<double>(k), 0, -300}, {static_cast<double>(k), 0, 300}, col, 1.0F);
    v.line({-300, 0, static_cast<double>(k)}, {300, 0, static_cast<double>(k)}, col, 1.0F);
  }
  v.line({0, 0, 0}, {60, 0, 0}, palette::kAxisX, 2.0F);
  v.line({0, 0, 0}, {0, 60, 0}, palette::kAxisY, 2.0F);
  v.line({0, 0, 0}, {0, 0, 60}, palette::kAxisZ, 2.0F);
}

// Each controller: its 80 × 30 mm top face where the layout puts it, plus a short view axis.
void draw_layout_controllers(const Canvas& v, const Layout& layout, std::vector<SlotLabel>& labels) {
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    const LayoutDevice& d = layout.devices[i];
    const ImU32 col = device_colour_u32(static_cast<int>(i));
    const Eigen::Vector3d c[4] = {d.to_world({-40, 0, -15}), d.to_world({40, 0, -15}), d.to_world({40, 0, 15}),
                                  d.to_world({-40, 0, 15})};
    for (int k = 0; k < 4; ++k) v.line(c[k], c[(k + 1) % 4], col, 2.0F);
    v.line(d.to_world({0, 0, 0}), d.to_world({0, 40, 0}), col, 1.0F);
    if (auto p = v.project(d.to_world({0, 0, 25}))) labels.push_back({*p, col, d.slot});
  }
}

// Scene items instead of the layout's controllers: ghosts as faint outlines, the others bold with
// their glass filled, segments as lines.
void draw_item_controllers(const Canvas& v, const std::vector<SceneItem>& items, const Layout& layout,
                           std::vector<SlotLabel>& labels) {
  for (const SceneItem& it : items) {
    const bool ghost = (it.flags & kFlagGhost) != 0;
    const ImU32 col = to_u32(it.colour);
    if (it.kind == ItemKind::kSegment) {
      v.line(it.a, it.b, col, 2.0F);
      continue;
    }
    if (it.kind != ItemKind::kBox) continue;
    if (!ghost) {
      // The solid box's glass filled, so it reads as the controller and the outline as its shadow.
      ImVec2 face[4];
      int n = 0;
      for (const auto& c : box_top_face(it)) {
        if (auto p = v.project(c)) face[n++] = ImVec2(static_cast<float>(p->x()), static_cast<float>(p->y()));
      }
      if (n == 4) v.draw_list()->AddConvexPolyFilled(face, 4, to_u32(it.colour, 0.45F));
    }
    for (const auto& e : box_edges(it)) v.line(e[0], e[1], col, ghost ? 1.0F : 2.5F);
    if (ghost || it.id < 0 || it.id >= layout.device_count()) continue;
    if (auto p = v.project(it.transform * Eigen::Vector3d(0, 0, 25)))
      labels.push_back({*p, col, layout.devices[static_cast<size_t>(it.id)].slot});
  }
}

// Every device's hand in the world frame (where the hands disagree, a device is misplaced), then
// the fused hand thick, each finger in its seen-by colour.
void draw_hands(const Canvas& v, const std::vector<LiveHand>& hands, const FusedHand* fused) {
  for (const auto& h : hands) {
    const ImU32 col = device_colour_u32(h.colour);
    for (const BoneSpec& b : hand_bones())
      v.line(h.world[static_cast<size_t>(b.from)], h.world[static_cast<size_t>(b.to)], col, 2.0F);
    if (auto p = v.project(h.world[kPalm]))
      v.draw_list()->AddCircleFilled(ImVec2(static_cast<float>(p->x()), static_cast<float>(p->y())), 4.0F, col);
  }
  if (fused == nullptr || !fused->has_hand) return;
  for (const BoneSpec& b : hand_bones()) {
    const Vec3& a = fused->points[static_cast<size_t>(b.from)];
    const Vec3& c = fused->points[static_cast<size_t>(b.to)];
    if (!a.allFinite() || !c.allFinite()) continue;
    const Rgba rgba =
        b.digit >= 0 ? seen_count_colour(fused->seen_by[static_cast<size_t>(b.digit)]) : Rgba{0.9F, 0.9F, 0.9F, 1.0F};
    v.line(a, c, to_u32(Rgba{rgba.r, rgba.g, rgba.b, 1.0F}), 5.0F);
  }
}

// The slots' names, spread so that two controllers standing close do not print over each other
// (the Layout scene's rule, ui/scene/label_spreading.h), with a shadow to read on the grid.
void draw_slot_labels(ImDrawList* dl, const std::vector<SlotLabel>& labels) {
  std::vector<LabelBox> boxes;
  for (const SlotLabel& l : labels) {
    const ImVec2 text = ImGui::CalcTextSize(l.text.c_str());
    boxes.push_back({static_cast<float>(l.at.x()) - 14, static_cast<float>(l.at.y()), text.x, text.y});
  }
  boxes = spread_labels(std::move(boxes), 1.0f);
  for (size_t i = 0; i < labels.size(); ++i) {
    dl->AddText(ImVec2(boxes[i].x + 1, boxes[i].y + 1), palette::kTextShadow, labels[i].text.c_str());
    dl->AddText(ImVec2(boxes[i].x, boxes[i].y), labels[i].colour, labels[i].text.c_str());
  }
}

}  // namespace

void draw_live_hands_view(const char* id, OrbitCamera& camera, const Layout& layout, const std::vector<LiveHand>& hands,
                          const std::string& caption, const FusedHand* fused,
                          const std::vector<SceneItem>* controllers) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  ImGui::InvisibleButton(id, ImVec2(std::max(size.x, 1.0F), std::max(size.y, 1.0F)));
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left))
    camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
    camera.zoom_towards(io.MousePos.x - origin.x, io.MousePos.y - origin.y, size.x, size.y, io.MouseWheel);
  }
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), palette::kPanelBackground);
  const Canvas view(dl, camera, origin, size);
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  draw_table_and_axes(view);
  std::vector<SlotLabel> labels;
  if (controllers == nullptr) {
    draw_layout_controllers(view, layout, labels);
  } else {
    draw_item_controllers(view, *controllers, layout, labels);
  }
  draw_hands(view, hands, fused);
  draw_slot_labels(dl, labels);  // after the hands: no hand line runs through a name
  dl->PopClipRect();
  // Wrapped to the canvas: a caption wider than a narrow view must not run off under the next panel.
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(origin.x + 8, origin.y + 6), palette::kViewCaption,
              caption.c_str(), nullptr, std::max(size.x - 16.0F, 1.0F));
}

}  // namespace lmc::ui
