#pragma once
// OpenGL 3.3 core renderer for the Layout tab's scene list. Renders into an offscreen framebuffer
// (4× multisampled when the driver allows, resolved into a texture) sized to the scene panel, so
// ImGui composes it like any image. The only file in ui/scene that touches GL.
#include <Eigen/Core>

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
  // True when the targets were made anew (their old picture is gone).
  bool ensure_targets(int w, int h);
  // True when the passes and the view are exactly those of the picture in the target.
  bool same_as_drawn(const Eigen::Matrix4f& view_projection);
  void release_targets();
  void draw(const std::vector<Vertex>& verts, unsigned mode);
  void fill_passes(const SceneList& scene);
  void draw_passes(const Eigen::Matrix4f& view_projection, const OrbitCamera& camera);

  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
  int u_vp_ = -1, u_view_dir_ = -1;
  unsigned msaa_fbo_ = 0, msaa_colour_ = 0, msaa_depth_ = 0;
  unsigned fbo_ = 0, texture_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0, samples_ = 4;
  // Reused every frame: no allocation once warmed up.
  std::vector<Vertex> opaque_, lines_, translucent_, translucent_lines_, xray_;
  // What the target shows: a view that did not change is not drawn again (a software renderer
  // pays tens of milliseconds a frame for it; any GPU, power).
  std::vector<Vertex> drawn_opaque_, drawn_lines_, drawn_translucent_, drawn_translucent_lines_, drawn_xray_;
  Eigen::Matrix4f drawn_view_projection_ = Eigen::Matrix4f::Zero();
  bool drawn_ = false;
};

}  // namespace lmc::ui
