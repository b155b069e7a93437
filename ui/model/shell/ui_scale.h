#pragma once
// How large the workbench draws on a high-DPI screen (a laptop at 150 %): one scale, from the
// window's content scale (GLFW: the monitor's DPI over 96 on Windows, Xft.dpi over 96 on X11) or
// the operator's --ui-scale, turned into the font's pixel size and the factor between ImGui's
// units and the window's pixels. The window keeps laying out in the units the tabs were made for
// (a 1280 × 800 window at 1.5 has 1920 × 1200 pixels and 1280 × 800 units), so every text, size
// and hit area grows by the same factor, the fixed widths in the panels included.
#include <optional>
#include <string>

namespace lmc::ui {

struct UiScale {
  float scale = 1.0F;     // window pixels per ImGui unit
  float font_px = 13.0F;  // the font atlas's glyph size in pixels: the built-in font's 13 × scale
  bool operator==(const UiScale&) const = default;
};

// The one rule: the override when given, else the content scale; anything not a positive number
// counts as 1; kept within [1, 3] (smaller text than the layouts were made for would cut it, and
// beyond 3 a 1280 × 800 layout fits no screen); rounded to a quarter, so a display at 97 dpi does
// not blur the built-in font and a content scale that wobbles by a hundredth rebuilds nothing.
UiScale choose_ui_scale(float content_scale, std::optional<float> override_scale = std::nullopt);

// `--ui-scale` as typed: "1.5", "150%" or "auto" (nullopt: follow the screen). False with
// `error` set for anything else, or a scale outside [1, 3].
bool parse_ui_scale(const std::string& text, std::optional<float>& scale, std::string& error);

// A length of `logical` ImGui units in window pixels (the window's size for a layout of that size).
int scaled_pixels(int logical, const UiScale& scale);

}  // namespace lmc::ui
