#include "ui/scene/gl_scene_renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/common/paths.h"
#include "ui/scene/software_renderer.h"

namespace lmc::ui {
namespace {

using Vertex = GlSceneRenderer::Vertex;

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read shader " + p.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

unsigned compile(GLenum type, const std::string& src, const std::string& name) {
  const unsigned s = glCreateShader(type);
  const char* text = src.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error("shader " + name + ": " + log);
  }
  return s;
}

void push(std::vector<Vertex>& v, const Eigen::Vector3d& p, const Rgba& c, const Eigen::Vector3d& n) {
  v.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), c.r, c.g, c.b, c.a,
               static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())});
}

void push_triangle(std::vector<Vertex>& v, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Rgba& col) {
  Eigen::Vector3d n = (b - a).cross(c - a);
  if (n.squaredNorm() > 0) n.normalize();
  push(v, a, col, n);
  push(v, b, col, n);
  push(v, c, col, n);
}

void push_quad(std::vector<Vertex>& v, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
               const Eigen::Vector3d& d, const Rgba& col) {
  push_triangle(v, a, b, c, col);
  push_triangle(v, a, c, d, col);
}

void push_box(std::vector<Vertex>& v, const SceneItem& it) {
  std::array<Eigen::Vector3d, 8> c;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d local = it.a + Eigen::Vector3d((i & 1) ? it.b.x() : -it.b.x(), (i & 2) ? it.b.y() : -it.b.y(),
                                                         (i & 4) ? it.b.z() : -it.b.z());
    c[static_cast<size_t>(i)] = it.transform * local;
  }
  // Faces wound counter-clockwise seen from outside.
  static constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : kFaces) {
    push_quad(v, c[static_cast<size_t>(f[0])], c[static_cast<size_t>(f[1])], c[static_cast<size_t>(f[2])],
              c[static_cast<size_t>(f[3])], it.colour);
  }
}

void push_bone(std::vector<Vertex>& v, const SceneItem& it) {
  const Eigen::Vector3d axis = it.b - it.a;
  const double len = axis.norm();
  if (len < 1e-6) return;
  const Eigen::Vector3d w = axis / len;
  const Eigen::Vector3d helper = std::abs(w.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u = w.cross(helper).normalized();
  const Eigen::Vector3d s = w.cross(u);
  constexpr int kSides = 8;
  for (int k = 0; k < kSides; ++k) {
    const double a0 = 2 * std::numbers::pi * k / kSides, a1 = 2 * std::numbers::pi * (k + 1) / kSides;
    const Eigen::Vector3d n0 = std::cos(a0) * u + std::sin(a0) * s;
    const Eigen::Vector3d n1 = std::cos(a1) * u + std::sin(a1) * s;
    const Eigen::Vector3d p0 = it.a + it.size * n0, p1 = it.a + it.size * n1;
    const Eigen::Vector3d q0 = it.b + it.size * n0, q1 = it.b + it.size * n1;
    push(v, p0, it.colour, n0);
    push(v, p1, it.colour, n1);
    push(v, q1, it.colour, n1);
    push(v, p0, it.colour, n0);
    push(v, q1, it.colour, n1);
    push(v, q0, it.colour, n0);
  }
}

// A unit sphere as a list of triangles, built once.
const std::vector<Eigen::Vector3d>& unit_sphere() {
  static const std::vector<Eigen::Vector3d> tris = [] {
    std::vector<Eigen::Vector3d> t;
    constexpr int kLat = 6, kLon = 10;
    const auto at = [](int i, int j) {
      const double th = std::numbers::pi * i / kLat, ph = 2 * std::numbers::pi * j / kLon;
      return Eigen::Vector3d(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
    };
    for (int i = 0; i < kLat; ++i) {
      for (int j = 0; j < kLon; ++j) {
        const auto a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        t.insert(t.end(), {a, b, c, a, c, d});
      }
    }
    return t;
  }();
  return tris;
}

void push_joint(std::vector<Vertex>& v, const SceneItem& it) {
  for (const auto& n : unit_sphere()) push(v, it.a + it.size * n, it.colour, n);
}

void push_pyramid(std::vector<Vertex>& v, const SceneItem& it) {
  const auto c = pyramid_corners(it.transform, it.size, it.b.x(), it.b.y());
  const Eigen::Vector3d apex = it.transform.translation();
  for (int k = 0; k < 4; ++k)
    push_triangle(v, apex, c[static_cast<size_t>(k)], c[static_cast<size_t>((k + 1) % 4)], it.colour);
  Rgba cap = it.colour;
  cap.a *= 0.6f;
  push_quad(v, c[0], c[1], c[2], c[3], cap);
}

void push_cell(std::vector<Vertex>& v, const SceneItem& it) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d a(it.a.x(), it.a.y(), it.a.z()), b(it.b.x(), it.a.y(), it.a.z());
  const Eigen::Vector3d c(it.b.x(), it.a.y(), it.b.z()), d(it.a.x(), it.a.y(), it.b.z());
  push(v, a, it.colour, n);
  push(v, b, it.colour, n);
  push(v, c, it.colour, n);
  push(v, a, it.colour, n);
  push(v, c, it.colour, n);
  push(v, d, it.colour, n);
}

}  // namespace

GlSceneRenderer::GlSceneRenderer() {
  const unsigned vs = compile(GL_VERTEX_SHADER, read_text(asset_path("shaders/scene.vert")), "scene.vert");
  const unsigned fs = compile(GL_FRAGMENT_SHADER, read_text(asset_path("shaders/scene.frag")), "scene.frag");
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("scene shader link: ") + log);
  }
  // A software rasteriser pays for every sample on the CPU: 4× MSAA there costs tens of
  // milliseconds per frame, so it renders without it.
  if (const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER))) {
    if (is_software_renderer(renderer)) samples_ = 0;
  }
  u_vp_ = glGetUniformLocation(program_, "u_view_projection");
  u_view_dir_ = glGetUniformLocation(program_, "u_view_dir");
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, r)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, nx)));
  glBindVertexArray(0);
}

GlSceneRenderer::~GlSceneRenderer() {
  release_targets();
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (program_) glDeleteProgram(program_);
}

void GlSceneRenderer::release_targets() {
  if (msaa_fbo_) glDeleteFramebuffers(1, &msaa_fbo_);
  if (msaa_colour_) glDeleteRenderbuffers(1, &msaa_colour_);
  if (msaa_depth_) glDeleteRenderbuffers(1, &msaa_depth_);
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (texture_) glDeleteTextures(1, &texture_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  msaa_fbo_ = msaa_colour_ = msaa_depth_ = fbo_ = texture_ = depth_ = 0;
  width_ = height_ = 0;
}

bool GlSceneRenderer::ensure_targets(int w, int h) {
  if (w == width_ && h == height_ && fbo_ != 0) return false;
  release_targets();
  width_ = w;
  height_ = h;
  // Resolve target: a plain texture ImGui can show, with its own depth for the no-MSAA path.
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (samples_ > 0) {
    glGenFramebuffers(1, &msaa_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
    glGenRenderbuffers(1, &msaa_colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, msaa_colour_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_colour_);
    glGenRenderbuffers(1, &msaa_depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      // No multisampling on this driver: fall back to the plain target from now on.
      glDeleteFramebuffers(1, &msaa_fbo_);
      glDeleteRenderbuffers(1, &msaa_colour_);
      glDeleteRenderbuffers(1, &msaa_depth_);
      msaa_fbo_ = msaa_colour_ = msaa_depth_ = 0;
      samples_ = 0;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return true;
}

void GlSceneRenderer::draw(const std::vector<Vertex>& verts, unsigned mode) {
  if (verts.empty()) return;
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts.size() * sizeof(Vertex)), verts.data(), GL_STREAM_DRAW);
  glDrawArrays(mode, 0, static_cast<GLsizei>(verts.size()));
}

// Sorts the scene's items into the passes' vertex lists.
void GlSceneRenderer::fill_passes(const SceneList& scene) {
  opaque_.clear();
  lines_.clear();
  translucent_.clear();
  translucent_lines_.clear();
  xray_.clear();
  for (const SceneItem& it : scene.items) {
    // The controllers' bodies hang below their origin, i.e. below the table plane (the study's
    // y = 0 is the sensor's top face): an x-ray pass shows the hidden parts dimmed.
    if (it.kind == ItemKind::kBox && (it.role == ItemRole::kDevice || it.role == ItemRole::kDeviceUsbMarker)) {
      SceneItem ghost = it;
      ghost.colour.a = 0.45f;
      push_box(xray_, ghost);
    }
    const bool translucent = (it.flags & (kFlagTranslucent | kFlagGhost)) != 0 || it.colour.a < 0.99f;
    if (it.kind == ItemKind::kSegment) {
      auto& dst = translucent ? translucent_lines_ : lines_;
      push(dst, it.a, it.colour, Eigen::Vector3d::Zero());
      push(dst, it.b, it.colour, Eigen::Vector3d::Zero());
      continue;
    }
    // Heatmap cells are nearly opaque and lie flat: draw them with the opaque pass so the grid
    // lines stay on top of them.
    auto& dst = (translucent && it.role != ItemRole::kHeatmap) ? translucent_ : opaque_;
    switch (it.kind) {
      case ItemKind::kBox:
        push_box(dst, it);
        break;
      case ItemKind::kPyramid:
        push_pyramid(dst, it);
        break;
      case ItemKind::kBone:
        push_bone(dst, it);
        break;
      case ItemKind::kJoint:
        push_joint(dst, it);
        break;
      case ItemKind::kCell:
        push_cell(dst, it);
        break;
      case ItemKind::kSegment:
        break;
    }
  }
}

// Opaque triangles and lines, then the translucent ones without depth writes (volumes behind one
// another all show), then the x-ray of what lies below the table.
void GlSceneRenderer::draw_passes(const Eigen::Matrix4f& view_projection, const OrbitCamera& camera) {
  const Eigen::Vector3f view_dir = camera.forward().cast<float>();
  glUseProgram(program_);
  glUniformMatrix4fv(u_vp_, 1, GL_FALSE, view_projection.data());  // Eigen is column-major, as GL expects
  glUniform3f(u_view_dir_, view_dir.x(), view_dir.y(), view_dir.z());
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glDepthMask(GL_TRUE);
  draw(opaque_, GL_TRIANGLES);
  draw(lines_, GL_LINES);
  glDepthMask(GL_FALSE);
  draw(translucent_, GL_TRIANGLES);
  draw(translucent_lines_, GL_LINES);
  glDepthFunc(GL_GREATER);
  draw(xray_, GL_TRIANGLES);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  glUseProgram(0);
}

namespace {

bool same_vertices(const std::vector<GlSceneRenderer::Vertex>& a, const std::vector<GlSceneRenderer::Vertex>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

}  // namespace

bool GlSceneRenderer::same_as_drawn(const Eigen::Matrix4f& view_projection) {
  if (drawn_ && view_projection == drawn_view_projection_ && same_vertices(opaque_, drawn_opaque_) &&
      same_vertices(lines_, drawn_lines_) && same_vertices(translucent_, drawn_translucent_) &&
      same_vertices(translucent_lines_, drawn_translucent_lines_) && same_vertices(xray_, drawn_xray_)) {
    return true;
  }
  drawn_ = true;
  drawn_view_projection_ = view_projection;
  drawn_opaque_ = opaque_;
  drawn_lines_ = lines_;
  drawn_translucent_ = translucent_;
  drawn_translucent_lines_ = translucent_lines_;
  drawn_xray_ = xray_;
  return false;
}

std::uintptr_t GlSceneRenderer::render(const SceneList& scene, const OrbitCamera& camera, int width_px, int height_px) {
  if (width_px < 8 || height_px < 8) return 0;
  if (ensure_targets(width_px, height_px)) drawn_ = false;
  fill_passes(scene);
  // The view direction follows from the view, which the view-projection holds.
  const Eigen::Matrix4f vp =
      (camera.projection(static_cast<double>(width_px) / height_px) * camera.view()).cast<float>();
  if (same_as_drawn(vp)) return static_cast<std::uintptr_t>(texture_);

  GLint prev_fbo = 0, prev_viewport[4];
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prev_fbo);
  glGetIntegerv(GL_VIEWPORT, prev_viewport);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_ ? msaa_fbo_ : fbo_);
  glViewport(0, 0, width_px, height_px);
  glClearColor(0.105f, 0.115f, 0.135f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_passes(vp, camera);
  if (msaa_fbo_) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    glBlitFramebuffer(0, 0, width_px, height_px, 0, 0, width_px, height_px, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(prev_fbo));
  glViewport(prev_viewport[0], prev_viewport[1], prev_viewport[2], prev_viewport[3]);
  return static_cast<std::uintptr_t>(texture_);
}

}  // namespace lmc::ui
