#pragma once
// What the scene panel needs from a renderer: draw a scene list for a camera into a w × h image
// and hand back a texture id for ImGui::Image. The GL implementation is gl_scene_renderer; tests
// use a recording renderer that keeps the last list instead of issuing GL calls (docs/architecture.md).
#include <cstdint>

#include "ui/scene/orbit_camera.h"
#include "ui/scene/scene_items.h"

namespace lmc::ui {

class SceneRenderer {
 public:
  virtual ~SceneRenderer() = default;
  // Returns an opaque texture id (0 = nothing to show).
  virtual std::uintptr_t render(const SceneList& scene, const OrbitCamera& camera, int width_px, int height_px) = 0;
};

}  // namespace lmc::ui
