#pragma once
// Headless Dear ImGui for panel tests (docs/architecture.md): a context with a built font
// atlas and no renderer. ImGui 1.86 predates the input-event queue, so input is written straight
// into ImGuiIO: a helper turns that into "move to, press, drag, release".
#include <imgui.h>

#include <functional>
#include <string>

namespace lmc::ui::testing {

class HeadlessImGui {
 public:
  explicit HeadlessImGui(float width = 1280, float height = 800) {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(width, height);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(1)));
    // The GLFW backend's key map (GLFW key codes), so the tab's shortcuts see the same indices.
    io.KeyMap[ImGuiKey_Escape] = 256;
    io.KeyMap[ImGuiKey_Enter] = 257;
    io.KeyMap[ImGuiKey_Tab] = 258;
    io.KeyMap[ImGuiKey_Backspace] = 259;
    io.KeyMap[ImGuiKey_Delete] = 261;
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyMap[ImGuiKey_Z] = 'Z';
    io.KeyMap[ImGuiKey_Y] = 'Y';
  }
  ~HeadlessImGui() { ImGui::DestroyContext(context_); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  // One frame: NewFrame, `body` (inside a full-screen window like the shell's), Render.
  void frame(const std::function<void()>& body) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("##test", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    body();
    ImGui::End();
    ImGui::Render();
  }
  void frames(int n, const std::function<void()>& body) {
    for (int i = 0; i < n; ++i) frame(body);
  }
  // One frame whose drawn text (labels, table cells, button captions) comes back as one string,
  // through ImGui's own log: a test asks whether a line is on screen, not at which pixel.
  std::string frame_text(const std::function<void()>& body) {
    ImGui::SetClipboardText("");  // the log leaves the clipboard as it was when nothing is drawn
    frame([&body] {
      ImGui::LogToClipboard();
      body();
      ImGui::LogFinish();
    });
    std::string text = ImGui::GetClipboardText() != nullptr ? ImGui::GetClipboardText() : "";
    while (!text.empty() && text.back() == '\n') text.pop_back();  // the log ends its last line
    return text;
  }

  // ---- input (applied to the next frame) -----------------------------------------------------
  void move_to(float x, float y) { ImGui::GetIO().MousePos = ImVec2(x, y); }
  void set_button(int button, bool down) { ImGui::GetIO().MouseDown[button] = down; }
  void set_key(int key, bool down) { ImGui::GetIO().KeysDown[key] = down; }
  void set_ctrl(bool on) { ImGui::GetIO().KeyCtrl = on; }
  void set_shift(bool on) { ImGui::GetIO().KeyShift = on; }

  // Hover, press, release at (x, y): a click takes three frames.
  void click(float x, float y, const std::function<void()>& body) {
    move_to(x, y);
    frame(body);
    set_button(0, true);
    frame(body);
    set_button(0, false);
    frame(body);
  }
  // Press at `from`, move in `steps` frames to `to`, release.
  void drag(ImVec2 from, ImVec2 to, int steps, const std::function<void()>& body, int button = 0) {
    move_to(from.x, from.y);
    frame(body);
    set_button(button, true);
    frame(body);
    for (int i = 1; i <= steps; ++i) {
      const float t = static_cast<float>(i) / static_cast<float>(steps);
      move_to(from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t);
      frame(body);
    }
    set_button(button, false);
    frame(body);
  }
  // Presses and releases a key (with the current modifiers) over two frames.
  void tap_key(int key, const std::function<void()>& body) {
    set_key(key, true);
    frame(body);
    set_key(key, false);
    frame(body);
  }

 private:
  ImGuiContext* context_ = nullptr;
};

}  // namespace lmc::ui::testing
