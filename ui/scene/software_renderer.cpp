#include "ui/scene/software_renderer.h"

#include <array>

namespace lmc::ui {

bool is_software_renderer(std::string_view gl_renderer) {
  // Mesa names its CPU drivers in the renderer string ("llvmpipe (LLVM 15.0.6, 256 bits)");
  // Windows' are Microsoft's GDI renderer and the Basic Render Driver (WARP) behind GLOn12.
  static constexpr std::array<std::string_view, 6> kCpuRenderers = {
      "llvmpipe", "softpipe", "Software Rasterizer", "SwiftShader", "GDI Generic", "Basic Render Driver"};
  for (const std::string_view name : kCpuRenderers) {
    if (gl_renderer.find(name) != std::string_view::npos) return true;
  }
  return false;
}

}  // namespace lmc::ui
