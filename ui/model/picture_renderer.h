#pragma once
// How a tab asks for a picture of some ImGui drawing at a chosen size, written as PNG: the program
// that owns the window provides it (ui/platform/offscreen_png.h); model tests have none.
#include <functional>
#include <string>

namespace lmc::ui {

using PictureRenderer =
    std::function<void(int width, int height, const std::string& png_path, const std::function<void()>& draw)>;

}  // namespace lmc::ui
