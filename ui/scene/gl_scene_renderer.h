#pragma once
// OpenGL 3.3 core renderer for the Layout tab's scene list. Renders into an offscreen framebuffer
// (4× multisampled when the driver allows, resolved into a texture) sized to the scene panel, so
// ImGui composes it like any image. The only file in ui/scene that touches GL.
#include <cstdint>
#include <vector>

#include "ui/scene/scene_renderer.h"

namespace lmc::ui {

class GlSceneRenderer final : public SceneRenderer {
 public:
  // Compiles the shaders from assets/shaders; throws std::runtime_error with the GL log on failure.
  GlSceneRenderer();
  ~GlSceneRenderer() override;
  GlSceneRenderer(const GlSceneRenderer&) = delete;
  GlSceneRenderer& operator=(const GlSceneRenderer&) = delete;

  std::uintptr_t render(const SceneList& scene, const OrbitCamera& camera, int width_px, int height_px) override;

  struct Vertex {
    float x, y, z;
    float r, g, b, a;
    float nx, ny, nz;
  };

 private:
  void ensure_targets(int w, int h);
  void release_targets();
  void draw(const std::vector<Vertex>& verts, unsigned mode);
  void fill_passes(const SceneList& scene);
  void draw_passes(const OrbitCamera& camera, int width_px, int height_px);

  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
  int u_vp_ = -1, u_view_dir_ = -1;
  unsigned msaa_fbo_ = 0, msaa_colour_ = 0, msaa_depth_ = 0;
  unsigned fbo_ = 0, texture_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0, samples_ = 4;
  // Reused every frame: no allocation once warmed up.
  std::vector<Vertex> opaque_, lines_, translucent_, translucent_lines_, xray_;
};

}  // namespace lmc::ui
