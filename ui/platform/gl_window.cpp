#include "ui/platform/gl_window.h"

// epoxy must come before GLFW so GLFW does not pull in a system GL header first.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>
#include <imgui.h>
#include <stb_image_write.h>

#include <cfloat>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "ui/platform/ui_fonts.h"
#include "ui/platform/user_config.h"
#include "ui/scene/software_renderer.h"

namespace lmc::ui {
namespace {

std::string g_last_glfw_error;

// ImGui 1.86 reads key state once per frame (io.KeysDown), so a press and its release between two
// frames vanish: at 13–16 fps under software rendering a quick Ctrl+Z tap worked 1 time in 7, and
// the Record tab is driven from the keyboard. A release that arrives in the same frame as its
// press is therefore held back and delivered at the start of the next frame, after ImGui has seen
// the key down once. (One window only, so file-level state is enough.)
struct HeldRelease {
  GLFWwindow* window;
  int key, scancode, mods;
};
GLFWkeyfun g_imgui_key_callback = nullptr;
std::vector<int> g_pressed_this_frame;
std::vector<HeldRelease> g_held_releases;

void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
  // Once a key went down this frame, every later release waits too, in order: Ctrl+Q typed
  // quickly (Q down, Q up, Ctrl up in one frame) must reach ImGui as Q with Ctrl still held.
  if (action == GLFW_RELEASE && !g_pressed_this_frame.empty()) {
    g_held_releases.push_back({window, key, scancode, mods});
    return;
  }
  if (action == GLFW_PRESS) g_pressed_this_frame.push_back(key);
  if (g_imgui_key_callback) g_imgui_key_callback(window, key, scancode, action, mods);
}

// Called before polling: the releases held back last frame reach ImGui now.
void deliver_held_releases() {
  std::vector<HeldRelease> held;
  held.swap(g_held_releases);
  g_pressed_this_frame.clear();
  for (const auto& r : held)
    if (g_imgui_key_callback) g_imgui_key_callback(r.window, r.key, r.scancode, GLFW_RELEASE, r.mods);
}

void on_glfw_error(int code, const char* description) {
  g_last_glfw_error = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

// ImGui's layout file belongs to the user, not the repository.
std::string user_ini_path() {
  const auto dir = user_config_dir();
  return dir.empty() ? std::string() : (dir / "imgui.ini").string();
}

}  // namespace

GlWindow::GlWindow(const WindowOptions& options) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    throw std::runtime_error("cannot open a window (" +
                             (g_last_glfw_error.empty() ? std::string("glfwInit failed") : g_last_glfw_error) +
                             "). Is a display available? Without one, run under xvfb-run.");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  // No multisampling of the window itself: ImGui smooths its own edges, and the 3D views render
  // into their own multisampled targets. Multisampling the window only multiplied the cost of
  // every pixel drawn, which a software renderer (Xvfb, a virtual machine) pays on the CPU.
  glfwWindowHint(GLFW_SAMPLES, 0);
  // Sized in units: GLFW scales the window by the monitor's content scale itself (and, on Windows,
  // again when it moves to a monitor of another DPI); an override scales it here instead.
  scale_override_ = options.ui_scale;
  const UiScale initial = choose_ui_scale(1.0F, scale_override_);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, scale_override_ ? GLFW_FALSE : GLFW_TRUE);
  window_ = glfwCreateWindow(scaled_pixels(options.width, initial), scaled_pixels(options.height, initial),
                             options.title.c_str(), nullptr, nullptr);
  glfwDefaultWindowHints();  // the subject screen's window sets its own
  if (window_ == nullptr) {
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window: " + g_last_glfw_error);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.visible ? 1 : 0);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  ini_path_ = options.visible ? user_ini_path() : std::string();
  io.IniFilename = ini_path_.empty() ? nullptr : ini_path_.c_str();
  float content_x = 1.0F, content_y = 1.0F;
  glfwGetWindowContentScale(window_, &content_x, &content_y);
  scale_ = choose_ui_scale(content_x, scale_override_);
  load_fonts();
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 3.0f;
  style.FrameRounding = 3.0f;
  style.TabRounding = 3.0f;
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  // After ImGui's backend installed its callbacks: ours runs first and forwards to it.
  g_imgui_key_callback = glfwSetKeyCallback(window_, on_key);
  glfwSetWindowUserPointer(window_, this);
  glfwSetWindowContentScaleCallback(window_, on_content_scale);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

void GlWindow::on_content_scale(GLFWwindow* window, float /*x*/, float /*y*/) {
  if (auto* self = static_cast<GlWindow*>(glfwGetWindowUserPointer(window))) self->content_scale_changed_ = true;
}

void GlWindow::load_fonts() {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  // The built-in font with DejaVu Sans merged in (dashes, arrows, ≤, µ …), rasterised at the
  // window's pixels and drawn at the 13 units the layouts are made for.
  load_ui_fonts(io, scale_.font_px);
  io.FontGlobalScale = 1.0F / scale_.scale;
}

void GlWindow::follow_content_scale() {
  content_scale_changed_ = false;
  float x = 1.0F, y = 1.0F;
  glfwGetWindowContentScale(window_, &x, &y);
  const UiScale next = choose_ui_scale(x, scale_override_);
  if (next == scale_) return;
  scale_ = next;
  load_fonts();
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}

void GlWindow::to_ui_units() const {
  ImGuiIO& io = ImGui::GetIO();
  const float s = scale_.scale;
  io.DisplaySize = ImVec2(io.DisplaySize.x / s, io.DisplaySize.y / s);
  io.DisplayFramebufferScale = ImVec2(io.DisplayFramebufferScale.x * s, io.DisplayFramebufferScale.y * s);
  if (io.MousePos.x > -FLT_MAX && io.MousePos.y > -FLT_MAX) io.MousePos = ImVec2(io.MousePos.x / s, io.MousePos.y / s);
}

GlWindow::~GlWindow() {
  if (window_) glfwSetKeyCallback(window_, g_imgui_key_callback);
  g_imgui_key_callback = nullptr;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlWindow::should_close() const {
  return glfwWindowShouldClose(window_) != 0;
}
void GlWindow::set_should_close(bool close) {
  glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE);
}
void GlWindow::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

void GlWindow::set_size(int units_wide, int units_high) {
  const int width = scaled_pixels(units_wide, scale_), height = scaled_pixels(units_high, scale_);
  glfwSetWindowSize(window_, width, height);
  for (int i = 0; i < 100 && (framebuffer_width() != width || framebuffer_height() != height); ++i) {
    glfwWaitEventsTimeout(0.01);
  }
}

void GlWindow::begin_frame() {
  deliver_held_releases();
  glfwPollEvents();
  if (content_scale_changed_) follow_content_scale();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  to_ui_units();
  ImGui::NewFrame();
}

void GlWindow::end_frame() {
  ImGui::Render();
  glViewport(0, 0, framebuffer_width(), framebuffer_height());
  glClearColor(0.10f, 0.11f, 0.13f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GlWindow::present() {
  glfwSwapBuffers(window_);
}

int GlWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GlWindow::monitor_refresh_hz() const {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
  return mode != nullptr ? mode->refreshRate : 0;
}

bool GlWindow::software_renderer() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer != nullptr && is_software_renderer(renderer);
}

int GlWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

void GlWindow::save_png(const std::string& path) const {
  write_back_buffer_png(path, framebuffer_width(), framebuffer_height());
}

void write_back_buffer_png(const std::string& path, int w, int h) {
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * static_cast<size_t>(h) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  stbi_flip_vertically_on_write(1);
  if (stbi_write_png(path.c_str(), w, h, 3, pixels.data(), w * 3) == 0) {
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace lmc::ui
