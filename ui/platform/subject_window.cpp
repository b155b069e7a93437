#include "ui/platform/subject_window.h"

// epoxy must come before GLFW so GLFW does not pull in a system GL header first.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>
#include <imgui.h>
#include <utility>

#include <filesystem>
#include <stdexcept>

#include "ui/platform/gl_window.h"
#include "ui/platform/ui_fonts.h"

namespace lmc::ui {
namespace {

// Keeps the caller's GL and ImGui contexts and puts them back when the frame is done.
class ContextSwitch {
 public:
  ContextSwitch(GLFWwindow* window, ImGuiContext* imgui)
      : gl_(glfwGetCurrentContext()), imgui_(ImGui::GetCurrentContext()) {
    glfwMakeContextCurrent(window);
    ImGui::SetCurrentContext(imgui);
  }
  ~ContextSwitch() {
    ImGui::SetCurrentContext(imgui_);
    glfwMakeContextCurrent(gl_);
  }
  ContextSwitch(const ContextSwitch&) = delete;
  ContextSwitch& operator=(const ContextSwitch&) = delete;

 private:
  GLFWwindow* gl_;
  ImGuiContext* imgui_;
};

int g_monitor_changes = 0;
void on_monitor(GLFWmonitor* /*monitor*/, int /*event*/) {
  ++g_monitor_changes;
}
}  // namespace

int monitor_changes() {
  static const bool watching = [] {
    glfwSetMonitorCallback(on_monitor);
    return true;
  }();
  (void)watching;
  return g_monitor_changes;
}

std::vector<Monitor> list_monitors() {
  std::vector<Monitor> out;
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  for (int i = 0; i < count; ++i) {
    Monitor m;
    const char* name = glfwGetMonitorName(monitors[i]);
    m.name = name ? name : "";
    glfwGetMonitorPos(monitors[i], &m.rect.x, &m.rect.y);
    if (const GLFWvidmode* mode = glfwGetVideoMode(monitors[i])) {
      m.rect.width = mode->width;
      m.rect.height = mode->height;
    }
    m.primary = i == 0;  // GLFW lists the primary monitor first
    out.push_back(std::move(m));
  }
  return out;
}

SubjectWindow::SubjectWindow(GLFWwindow* share, const SubjectWindowOptions& options) : options_(options) {
  int w = options.place.width, h = options.place.height;
  if (!options.visible) {
    w = options.width;
    h = options.height;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once placed
  // Borderless over the whole monitor rather than an exclusive full-screen mode: no mode switch,
  // and the operator's window on the other monitor is left alone.
  glfwWindowHint(GLFW_DECORATED, options.windowed || !options.visible ? GLFW_TRUE : GLFW_FALSE);
  // The operator drives the session from the keyboard: the subject screen must not take focus.
  glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
  glfwWindowHint(GLFW_FOCUS_ON_SHOW, GLFW_FALSE);
  // The title says how it closes: the subject screen has no controls of its own.
  window_ = glfwCreateWindow(w, h, "Subject screen (F2 in the workbench closes it)", nullptr, share);
  glfwDefaultWindowHints();
  if (window_ == nullptr) throw std::runtime_error("cannot open the subject screen window (GLFW could not create it)");
  if (options.visible) {
    glfwSetWindowPos(window_, options.place.x, options.place.y);
    glfwShowWindow(window_);
  }

  GLFWwindow* previous_gl = glfwGetCurrentContext();
  ImGuiContext* previous_imgui = ImGui::GetCurrentContext();
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the main window waits for the display; this one must not wait again
  // A context with a font atlas of its own: the main window's keeps its small font.
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  ImGui::StyleColorsDark();
  const float normal = options.normal_font_px > 0 ? options.normal_font_px : 28.0F;
  fonts_.normal = add_large_ui_font(io, normal);
  fonts_.large = add_large_ui_font(io, normal * 2.0F);
  fonts_.huge = add_large_ui_font(io, normal * 150.0F / 28.0F);
  ImGui_ImplGlfw_InitForOpenGL(window_, false);  // no callbacks: no controls, no input
  ImGui_ImplOpenGL3_Init("#version 330 core");
  ImGui::SetCurrentContext(previous_imgui);
  glfwMakeContextCurrent(previous_gl);
}

SubjectWindow::~SubjectWindow() {
  {
    ContextSwitch to(window_, imgui_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
  }
  ImGui::DestroyContext(imgui_);
  glfwDestroyWindow(window_);
}

void window_placement(GLFWwindow* window, int& x, int& y, int& width, int& height) {
  glfwGetWindowPos(window, &x, &y);
  glfwGetWindowSize(window, &width, &height);
}

void SubjectWindow::placement(int& x, int& y, int& width, int& height) const {
  window_placement(window_, x, y, width, height);
}

bool SubjectWindow::closed_by_user() const {
  return glfwWindowShouldClose(window_) != 0;
}

void SubjectWindow::frame(const std::function<void(const SubjectFonts&)>& body, const std::string& png_path) {
  ContextSwitch to(window_, imgui_);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  body(fonts_);
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glViewport(0, 0, w, h);
  glClearColor(0.0F, 0.0F, 0.0F, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!png_path.empty()) write_back_buffer_png(png_path, w, h);
  glfwSwapBuffers(window_);
}

}  // namespace lmc::ui
