#pragma once
// Whether the OpenGL renderer draws on the CPU: Mesa's llvmpipe and softpipe (Xvfb, virtual
// machines, a remote desktop without a GPU), Windows' fall-backs. There every pixel costs CPU that
// recording and fusion need, so the window draws more sparingly (no multisampled 3D views, a lower
// frame rate).
#include <string_view>

namespace lmc::ui {

// `gl_renderer` as glGetString(GL_RENDERER) gives it.
bool is_software_renderer(std::string_view gl_renderer);

}  // namespace lmc::ui
