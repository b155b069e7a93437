#pragma once
// A picture of ImGui drawing at a size the user chooses, rendered off screen and written as PNG
// (every plot and figure as PNG). It draws in a hidden second window with its own ImGui
// context that shares the main window's GL objects — the subject screen's window, which is made
// for exactly that — so the main window's layout and size are left alone.
#include <functional>
#include <string>

struct GLFWwindow;

namespace lmc::ui {

// `draw` runs inside a window filling the picture. Throws std::runtime_error when the window cannot
// be made or the PNG cannot be written.
void render_offscreen_png(GLFWwindow* share, int width, int height, const std::string& png_path,
                          const std::function<void()>& draw);

}  // namespace lmc::ui
