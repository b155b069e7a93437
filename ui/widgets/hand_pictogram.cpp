#include "ui/widgets/hand_pictogram.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ui/scene/orbit_camera.h"
#include "ui/scene/scene_items.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

// A view that shows each motion's movement: fingers and the wrist bend about axes across the hand,
// so a view from the side shows them; with the palm turned to the side (vertical), from above.
OrbitCamera pictogram_camera(const MotionPictogram& p, double aspect) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = Eigen::Vector3d::Constant(-1e9);
  for (const HandFrame* f : {&p.start, &p.end}) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      // The hand fills the box; the forearm runs out of it (the elbow is far from the motion).
      if (i == kPalmNormal || i == kPalmDirection || i == kElbow) continue;
      lo = lo.cwiseMin(f->point(i));
      hi = hi.cwiseMax(f->point(i));
    }
  }
  OrbitCamera cam;
  const bool vertical = p.orientation == HandOrientation::kVertical;
  cam.set(0.5 * (lo + hi), vertical ? -25.0 : -55.0, vertical ? 60.0 : 42.0, 600.0);
  cam.frame_bounds(lo, hi, aspect);
  // frame_bounds fits the box's bounding sphere; a hand is long and flat, so come closer.
  cam.set(cam.target(), cam.yaw_deg(), cam.pitch_deg(), 0.9 * cam.distance_mm());
  return cam;
}

struct Stroke {
  double depth;
  bool joint;
  ImVec2 a, b;
  float width;
  ImU32 colour;
};

}  // namespace

void draw_hand_pictogram(const MotionPictogram& p, ImVec2 size) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), palette::kPanelBackground, 6.0F);
  if (size.x < 8 || size.y < 8) return;
  const OrbitCamera cam = pictogram_camera(p, static_cast<double>(size.x / size.y));
  const auto project = [&](const Eigen::Vector3d& w) -> std::optional<ImVec2> {
    const auto q = cam.project(w, size.x, size.y);
    if (!q) return std::nullopt;
    return ImVec2(origin.x + static_cast<float>(q->x()), origin.y + static_cast<float>(q->y()));
  };
  // World radius → pixels at that point's distance.
  const auto pixels = [&](const Eigen::Vector3d& at, double radius_mm) {
    const auto a = project(at);
    const auto b = project(at + cam.right() * radius_mm);
    return a && b ? std::max(1.0F, std::abs(b->x - a->x)) : 1.0F;
  };
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  // Start and end poses: thin outlines (the end in amber: where the motion goes).
  const auto outline = [&](const HandFrame& f, ImU32 colour) {
    for (const BoneSpec& b : hand_bones()) {
      const auto a = project(f.point(b.from));
      const auto c = project(f.point(b.to));
      if (a && c) dl->AddLine(*a, *c, colour, 2.0F);
    }
  };
  outline(p.start, palette::kPoseStart);
  if (p.motion != HandMotion::kOpen) outline(p.end, palette::kPoseEnd);
  // The animated hand: the Layout tab's hand items, far to near so nearer bones cover farther ones.
  SceneInputs in;
  in.hand = &p.now;
  const SceneList scene = build_scene(in);
  std::vector<Stroke> strokes;
  for (const SceneItem& it : scene.items) {
    if (it.role != ItemRole::kHand && it.role != ItemRole::kFinger) continue;
    if (it.kind == ItemKind::kBone) {
      const auto a = project(it.a);
      const auto b = project(it.b);
      if (!a || !b) continue;
      const Eigen::Vector3d mid = 0.5 * (it.a + it.b);
      strokes.push_back(
          {(mid - cam.eye()).norm(), false, *a, *b, 2.0F * pixels(mid, it.size), to_u32(it.colour, 1.0F)});
    } else if (it.kind == ItemKind::kJoint) {
      const auto a = project(it.a);
      if (!a) continue;
      strokes.push_back({(it.a - cam.eye()).norm(), true, *a, *a, pixels(it.a, it.size), to_u32(it.colour, 1.0F)});
    }
  }
  std::sort(strokes.begin(), strokes.end(), [](const Stroke& x, const Stroke& y) { return x.depth > y.depth; });
  for (const Stroke& s : strokes) {
    if (s.joint) {
      dl->AddCircleFilled(s.a, s.width, s.colour, 16);
      dl->AddCircle(s.a, s.width, palette::kJointOutline, 16, 1.0F);
    } else {
      dl->AddLine(s.a, s.b, palette::kBoneOutline, s.width + 2.0F);
      dl->AddLine(s.a, s.b, s.colour, s.width);
    }
  }
  dl->PopClipRect();
}

}  // namespace lmc::ui
