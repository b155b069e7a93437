#include "ui/platform/ui_fonts.h"

#include <cstdlib>
#include <system_error>
#include <vector>

#include "core/common/paths.h"

namespace lmc::ui {

const ImWchar* ui_text_glyph_ranges() {
  static const ImWchar ranges[] = {
      0x0020, 0x00FF,  // Basic Latin, Latin-1 (·, ±, °, µ, ×, é)
      0x0100, 0x017F,  // Latin Extended-A (names: ł, ő, š)
      0x0370, 0x03FF,  // Greek (μ, σ, Δ, θ)
      0x2010, 0x206F,  // General Punctuation (‐ – — ‘ ’ “ ” • … ′ ″)
      0x2070, 0x209F,  // superscripts and subscripts (², ₀ … ₉)
      0x2190, 0x21FF,  // arrows (← → ↑ ↓ ↔)
      0x2200, 0x22FF,  // mathematical operators (− ≤ ≥ ≈ ≠ ∞ √ ∑)
      0x2300, 0x23FF,  // technical (⌀, ⏎)
      0x25A0, 0x25FF,  // geometric shapes (■ ▲ ▶ ● ○)
      0x2600, 0x26FF,  // symbols (⚠)
      0x2713, 0x2717,  // check and cross marks (✓ ✗)
      0,
  };
  return ranges;
}

std::filesystem::path ui_font_file(bool bold) {
  const char* name = bold ? "DejaVuSans-Bold.ttf" : "DejaVuSans.ttf";
  std::vector<std::filesystem::path> candidates = {
      // A packed build (the Windows zip) may carry the font with its assets.
      lmc::assets_dir() / "fonts" / name,
      std::filesystem::path("/usr/share/fonts/truetype/dejavu") / name,
  };
#ifdef _WIN32
  // Without DejaVu Sans, Windows' own UI font has the dashes, arrows, Greek and most symbols.
  if (const char* windows = std::getenv("WINDIR"); windows != nullptr && *windows != '\0')
    candidates.push_back(std::filesystem::path(windows) / "Fonts" / (bold ? "segoeuib.ttf" : "segoeui.ttf"));
#endif
  std::error_code ec;
  for (const auto& file : candidates)
    if (std::filesystem::is_regular_file(file, ec)) return file;
  return {};
}

bool load_ui_fonts(ImGuiIO& io, float size_px) {
  ImFontConfig base;
  base.SizePixels = size_px;
  io.Fonts->AddFontDefault(&base);
  const std::filesystem::path file = ui_font_file();
  if (file.empty()) return false;
  ImFontConfig merge;
  merge.MergeMode = true;
  // DejaVu Sans at the built-in font's size has the same x-height, so merged glyphs sit on the
  // same line and the layouts keep their widths.
  merge.GlyphOffset = ImVec2(0.0F, 0.0F);
  merge.PixelSnapH = true;
  return io.Fonts->AddFontFromFileTTF(file.string().c_str(), size_px, &merge, ui_text_glyph_ranges()) != nullptr;
}

ImFont* add_large_ui_font(ImGuiIO& io, float size_px) {
  if (const std::filesystem::path file = ui_font_file(true); !file.empty()) {
    if (ImFont* f = io.Fonts->AddFontFromFileTTF(file.string().c_str(), size_px, nullptr, ui_text_glyph_ranges()))
      return f;
  }
  ImFontConfig config;
  config.SizePixels = size_px;
  return io.Fonts->AddFontDefault(&config);
}

}  // namespace lmc::ui
