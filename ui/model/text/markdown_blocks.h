#pragma once
// The small part of Markdown that our reports use (`lmc report`'s study tables): headings, bullet
// lines, paragraphs and pipe tables, split into blocks so the Review tab can show a report as
// ImGui tables instead of raw text. Anything else is a paragraph; nothing here draws.
#include <string>
#include <vector>

namespace lmc::ui {

struct MarkdownBlock {
  enum class Kind { kHeading, kBullet, kParagraph, kTable };
  Kind kind = Kind::kParagraph;
  int level = 0;                               // headings: 1 for "#", 2 for "##", …
  std::string text;                            // headings, bullets, paragraphs (without the marker)
  std::vector<std::string> header;             // tables
  std::vector<bool> right_aligned;             // tables: from the "---:" separator
  std::vector<std::vector<std::string>> rows;  // tables
};

std::vector<MarkdownBlock> parse_markdown_blocks(const std::string& text);

}  // namespace lmc::ui
