#include "core/figures/svg_text.h"

#include <algorithm>

#include "core/common/xml_text.h"
#include "core/figures/svg_marks.h"

namespace lmc::svg {

double text_width(std::string_view s, double font) {
  size_t n = 0;
  for (const char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0u) != 0x80u) ++n;
  return static_cast<double>(n) * kCharWidth * font;
}

std::vector<std::string> wrap_words(std::string_view s, double max_width, double font) {
  std::vector<std::string> lines(1);
  size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ') {
      ++i;
      continue;
    }
    const size_t end = std::min(s.find(' ', i), s.size());
    const std::string_view word = s.substr(i, end - i);
    std::string& line = lines.back();
    if (line.empty())
      line = word;
    else if (text_width(line, font) + text_width(" ", font) + text_width(word, font) <= max_width)
      line += " " + std::string(word);
    else
      lines.emplace_back(word);
    i = end;
  }
  return lines;
}

void text(std::string& out, double x, double y, std::string_view s, std::string_view anchor, double font,
          std::string_view extra) {
  out += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + std::string(anchor) + "\"";
  if (font != kFont) out += " font-size=\"" + num(font) + "\"";
  out += std::string(extra) + ">" + xml_escape(s) + "</text>\n";
}

void document_start(std::string& out, int w, int h, const std::string& title) {
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(w) + "\" height=\"" +
         std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) +
         "\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"" + num(kFont) + "\">\n";
  out += "<title>" + xml_escape(title) + "</title>\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) +
         "\" fill=\"#ffffff\"/>\n";
}

double title_band(std::string& out, int w, const std::string& title) {
  if (title.empty()) return 8;
  text(out, w / 2.0, 8 + kTitleFont, title, "middle", kTitleFont, " font-weight=\"bold\"");
  return 8 + kTitleFont + 10;
}

}  // namespace lmc::svg
