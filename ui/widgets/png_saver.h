#pragma once
// "PNG..." beside a plot: a small popup asks for the picture's size, a file browser for
// where, and the picture is rendered off screen at that size (ui/model/picture_renderer.h)
// by the same drawing code the screen uses. Success or the error shows beside the button.
#include <functional>
#include <string>

#include "ui/model/picture_renderer.h"
#include "ui/widgets/file_browser.h"

namespace lmc::ui {

class PngSaver {
 public:
  // `picture` draws what goes into the PNG (it runs inside the off-screen window, during this call,
  // so it may refer to the caller's locals). Without a renderer (no window) the button is disabled.
  void draw(const char* id, const PictureRenderer& renderer, const std::string& default_name,
            const std::function<void()>& picture);

  PngSaver(int width, int height) : width_(width), height_(height) {}

 private:
  int width_, height_;
  FileBrowser browser_{"Save the picture as PNG", ".png"};
  std::string message_;
};

}  // namespace lmc::ui
