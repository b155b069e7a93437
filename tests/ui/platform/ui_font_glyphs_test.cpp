// The font draws what we write: every character outside ASCII in a string literal of ui/, core/
// and devices/ (the workbench shows messages from all three) has a glyph in the font the main
// window loads, and in the subject screen's large font, so none is drawn as '?'. Fails, naming
// the character and where it is written, when a new one is used that the fonts lack.
#include <gtest/gtest.h>

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "tests/support/build_paths.h"
#include "ui/platform/ui_fonts.h"

namespace lmc::ui {
namespace ui_font_glyphs_test {  // named: test files share unity batches

namespace fs = std::filesystem;

// Each code point above 0x7F found inside a string or character literal, with its first place.
class LiteralScanner {
 public:
  void scan_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    const std::string where = fs::relative(file, test::source_dir()).string();
    int line = 1;
    size_t i = 0;
    const auto at = [&](size_t k) { return k < text.size() ? text[k] : '\0'; };
    while (i < text.size()) {
      const char c = text[i];
      if (c == '\n') {
        ++line;
        ++i;
      } else if (c == '/' && at(i + 1) == '/') {
        while (i < text.size() && text[i] != '\n') ++i;
      } else if (c == '/' && at(i + 1) == '*') {
        i += 2;
        while (i < text.size() && !(text[i] == '*' && at(i + 1) == '/')) line += text[i++] == '\n' ? 1 : 0;
        i += 2;
      } else if (c == 'R' && at(i + 1) == '"') {
        // R"delim( … )delim"
        const size_t open = text.find('(', i + 2);
        if (open == std::string::npos) break;
        const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
        const size_t end = text.find(close, open);
        const size_t stop = end == std::string::npos ? text.size() : end;
        collect(text, open + 1, stop, where, line);
        for (size_t k = i; k < stop; ++k) line += text[k] == '\n' ? 1 : 0;
        i = stop + close.size();
      } else if (c == '"' || (c == '\'' && !std::isalnum(static_cast<unsigned char>(at(i - 1))))) {
        // A literal to its closing quote (a digit separator like 1'000 is not one).
        size_t k = i + 1;
        while (k < text.size() && text[k] != c && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
        collect(text, i + 1, std::min(k, text.size()), where, line);
        i = k + 1;
      } else {
        ++i;
      }
    }
  }
  const std::map<std::uint32_t, std::string>& found() const { return found_; }

 private:
  void collect(const std::string& text, size_t from, size_t to, const std::string& where, int line) {
    for (size_t k = from; k < to;) {
      const auto b = static_cast<unsigned char>(text[k]);
      int extra = 0;
      std::uint32_t cp = b;
      if (b >= 0xF0) {
        extra = 3;
        cp = b & 0x07U;
      } else if (b >= 0xE0) {
        extra = 2;
        cp = b & 0x0FU;
      } else if (b >= 0xC0) {
        extra = 1;
        cp = b & 0x1FU;
      }
      for (int e = 1; e <= extra && k + static_cast<size_t>(e) < to; ++e)
        cp = (cp << 6U) | (static_cast<unsigned char>(text[k + static_cast<size_t>(e)]) & 0x3FU);
      if (cp > 0x7F) found_.emplace(cp, where + ":" + std::to_string(line));
      k += 1 + static_cast<size_t>(extra);
    }
  }
  std::map<std::uint32_t, std::string> found_;
};

std::string utf8(std::uint32_t cp) {
  std::string s;
  if (cp < 0x800) {
    s += static_cast<char>(0xC0 | (cp >> 6U));
  } else if (cp < 0x10000) {
    s += static_cast<char>(0xE0 | (cp >> 12U));
    s += static_cast<char>(0x80 | ((cp >> 6U) & 0x3FU));
  } else {
    s += static_cast<char>(0xF0 | (cp >> 18U));
    s += static_cast<char>(0x80 | ((cp >> 12U) & 0x3FU));
    s += static_cast<char>(0x80 | ((cp >> 6U) & 0x3FU));
  }
  s += static_cast<char>(0x80 | (cp & 0x3FU));
  return s;
}

TEST(UiFontGlyphs, EveryCharacterTheSourcesWriteHasAGlyphInTheWorkbenchsFonts) {
  LiteralScanner scanner;
  int files = 0;
  for (const char* folder : {"ui", "core", "devices"}) {
    for (const auto& e : fs::recursive_directory_iterator(test::source_dir() / folder)) {
      const auto ext = e.path().extension();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      scanner.scan_file(e.path());
      ++files;
    }
  }
  ASSERT_GT(files, 100) << "the sources were not found under " << test::source_dir();
  // The scan sees what the workbench writes: the dash of "aborted before go — no data" at least.
  ASSERT_TRUE(scanner.found().contains(0x2014)) << "no em dash found: the literal scanner is broken";

  ASSERT_FALSE(ui_font_file().empty()) << "DejaVu Sans is missing: install fonts-dejavu-core (scripts/install-deps)";
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  ASSERT_TRUE(load_ui_fonts(io));
  ImFont* large = add_large_ui_font(io, 40.0F);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  ImFont* main = io.Fonts->Fonts[0];
  for (const auto& [cp, where] : scanner.found()) {
    if (cp > 0xFFFF) {
      ADD_FAILURE() << "U+" << std::hex << cp << " (" << utf8(cp) << ") at " << where
                    << " is outside the 16-bit range ImGui 1.86 draws";
      continue;
    }
    const auto c = static_cast<ImWchar>(cp);
    EXPECT_NE(main->FindGlyphNoFallback(c), nullptr)
        << "U+" << std::hex << cp << " (" << utf8(cp) << ") written at " << where << " has no glyph: drawn as '?'";
    EXPECT_NE(large->FindGlyphNoFallback(c), nullptr) << "U+" << std::hex << cp << " (" << utf8(cp) << ") written at "
                                                      << where << " is missing on the subject screen";
  }
  // ASCII and Latin-1 still come from the built-in font, so the layouts keep their widths.
  EXPECT_FLOAT_EQ(main->FindGlyph('W')->AdvanceX, 7.0F);
  ImGui::DestroyContext(context);
}

}  // namespace ui_font_glyphs_test
}  // namespace lmc::ui
