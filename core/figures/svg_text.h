#pragma once
// The pieces every exported SVG document shares: its opening (size, font, white background,
// <title>), the bold title band, a line of text and the estimate of how wide text is. One place,
// so a plot and a heatmap exported side by side use the same fonts and title. Internal to
// core/figures.
#include <string>
#include <string_view>
#include <vector>

namespace lmc::svg {

inline constexpr double kFont = 12.0;        // tick labels, legend, notes, cell values
inline constexpr double kTitleFont = 15.0;   // the document's title
inline constexpr double kPanelFont = 13.0;   // a panel's own title
inline constexpr double kCharWidth = 0.6;    // an average sans-serif glyph, in em: text is never measured
inline constexpr double kLineHeight = 18.0;  // one row of legend or notes

// Width of text on one line, from its code-point count (continuation bytes are not counted).
double text_width(std::string_view s, double font = kFont);

// The words of `s` in lines no wider than `max_width` where possible, greedily; a single word
// wider than that gets a line of its own (the caller decides what to do with it). Never empty.
std::vector<std::string> wrap_words(std::string_view s, double max_width, double font = kFont);

// <text> at (x, y) with anchor "start" / "middle" / "end"; `extra` is more attributes, written
// as given (leading space included). The text is escaped (xml_text.h).
void text(std::string& out, double x, double y, std::string_view s, std::string_view anchor, double font = kFont,
          std::string_view extra = {});

// The XML declaration, the <svg> element with its size and font, <title> and a white background.
void document_start(std::string& out, int w, int h, const std::string& title);

// Writes the title centred at the top; returns the height the band takes (a small top margin
// without a title).
double title_band(std::string& out, int w, const std::string& title);

}  // namespace lmc::svg
