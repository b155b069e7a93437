#pragma once
// The fonts every window of the workbench draws its text with, and the characters they must hold.
// ImGui's built-in font has Latin-1 only, while our text uses dashes, minus signs, arrows, ≤ ≥,
// subscripts, µ and Greek letters; without them ImGui draws '?'. So the built-in font (whose
// metrics the layouts are made for) is kept for ASCII and Latin-1, and DejaVu Sans (Debian's
// fonts-dejavu-core, which scripts/install-deps installs) is merged in for the rest.
#include <imgui.h>

#include <filesystem>

namespace lmc::ui {

// The code point ranges the UI's text uses beyond ASCII, as ImGui's zero-terminated pairs.
const ImWchar* ui_text_glyph_ranges();

// DejaVu Sans (regular or bold): in the assets' fonts folder (a packed build), else where Debian
// installs it; on Windows without either, Segoe UI. Empty when none is there.
std::filesystem::path ui_font_file(bool bold = false);

// The main window's font at `size_px` (13: the built-in font's own size; more on a high-DPI
// screen): the built-in one with DejaVu Sans merged in for ui_text_glyph_ranges(). Returns false
// (the built-in font alone) when DejaVu Sans is missing.
bool load_ui_fonts(ImGuiIO& io, float size_px = 13.0F);

// A font of `size_px` for the subject screen: DejaVu Sans Bold with every range the UI uses, else
// the built-in font scaled.
ImFont* add_large_ui_font(ImGuiIO& io, float size_px);

}  // namespace lmc::ui
