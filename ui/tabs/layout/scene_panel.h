#pragma once
// The 3D scene of the Layout tab: builds the scene list from the tab state, has the renderer draw
// it into an image sized to the panel, and turns mouse gestures into camera moves, selection and
// handle drags. Input layers, top first: handles of the selected controller, then controllers
// (press selects and starts a move), then the camera (left-drag on empty space orbits,
// right/middle-drag pans, the wheel zooms towards the cursor). A click on empty space (press and
// release without moving) clears the selection. Escape during a drag puts the controller back.
#include <functional>
#include <memory>

#include <imgui.h>

#include "ui/model/layout/layout_state.h"
#include "ui/scene/drag_controller.h"
#include "ui/scene/scene_renderer.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class ScenePanel : public Panel {
 public:
  // `renderer` is asked for lazily (the GL one needs the window's context).
  ScenePanel(std::shared_ptr<LayoutState> state, std::function<SceneRenderer*()> renderer);

  void draw(ImVec2 size);

  // Where the scene image was drawn last frame (screen pixels), for tests and tooltips.
  ImVec2 image_min() const { return image_min_; }
  ImVec2 image_size() const { return image_size_; }
  // Frames everything (the F key).
  void frame_all();
  const SceneList& last_scene() const { return scene_; }

 private:
  enum class Gesture { kNone, kHandle, kOrbit, kPan };
  void handle_input(bool hovered);
  void update_hover(bool hovered, ImVec2 mouse_in_image);
  void begin_gesture(bool hovered);
  void continue_drag(float moved_px);  // moved_px: how far the pointer is from the press (|dx| + |dy|)
  struct OverlayPlaces;
  OverlayPlaces place_overlays() const;
  void draw_overlays(ImDrawList* dl);
  void draw_labels(ImDrawList* dl, const OverlayPlaces& o) const;
  static void draw_finger_legend(ImDrawList* dl, const OverlayPlaces& o);
  void draw_heat_bar(ImDrawList* dl, const OverlayPlaces& o) const;
  void draw_tooltips() const;
  Ray mouse_ray() const;
  int pick_device(const Ray& ray) const;

  std::shared_ptr<LayoutState> state_;
  std::function<SceneRenderer*()> renderer_;
  SceneList scene_;
  ImVec2 image_min_{0, 0}, image_size_{1, 1};
  Gesture gesture_ = Gesture::kNone;
  DragController drag_;
  int drag_device_ = -1;
  ImVec2 press_pos_{0, 0};
  bool moved_ = false;
  bool frame_requested_ = true;  // frame everything on the first draw
};

}  // namespace lmc::ui
