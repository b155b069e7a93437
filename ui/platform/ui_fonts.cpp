#include "ui/platform/ui_fonts.h"

#include <system_error>

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
  const std::filesystem::path file =
      bold ? "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf" : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code ec;
  return std::filesystem::is_regular_file(file, ec) ? file : std::filesystem::path();
}

bool load_ui_fonts(ImGuiIO& io) {
  ImFontConfig base;
  io.Fonts->AddFontDefault(&base);
  const std::filesystem::path file = ui_font_file();
  if (file.empty()) return false;
  ImFontConfig merge;
  merge.MergeMode = true;
  // The built-in font is 13 px; DejaVu Sans at 13 px has the same x-height, so merged glyphs sit
  // on the same line and the layouts keep their widths.
  merge.GlyphOffset = ImVec2(0.0F, 0.0F);
  merge.PixelSnapH = true;
  return io.Fonts->AddFontFromFileTTF(file.string().c_str(), 13.0F, &merge, ui_text_glyph_ranges()) != nullptr;
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
