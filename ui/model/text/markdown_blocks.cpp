#include "ui/model/text/markdown_blocks.h"

#include <sstream>
#include <utility>

namespace lmc::ui {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// "| a | b |" → {"a", "b"}.
std::vector<std::string> cells_of(const std::string& line) {
  std::string body = trim(line);
  if (!body.empty() && body.front() == '|') body.erase(0, 1);
  if (!body.empty() && body.back() == '|') body.pop_back();
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(body);
  while (std::getline(in, cell, '|')) cells.push_back(trim(cell));
  if (!body.empty() && body.back() == '|') cells.emplace_back();
  return cells;
}

bool is_separator(const std::vector<std::string>& cells) {
  if (cells.empty()) return false;
  for (const auto& c : cells) {
    if (c.empty() || c.find_first_not_of(":-") != std::string::npos || c.find('-') == std::string::npos) return false;
  }
  return true;
}

}  // namespace

std::vector<MarkdownBlock> parse_markdown_blocks(const std::string& text) {
  std::vector<MarkdownBlock> blocks;
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line = trim(lines[i]);
    if (line.empty()) continue;
    MarkdownBlock b;
    if (line.front() == '#') {
      const auto marks = line.find_first_not_of('#');
      b.kind = MarkdownBlock::Kind::kHeading;
      b.level = static_cast<int>(marks == std::string::npos ? line.size() : marks);
      b.text = marks == std::string::npos ? std::string() : trim(line.substr(marks));
    } else if (line.rfind("* ", 0) == 0 || line.rfind("- ", 0) == 0) {
      b.kind = MarkdownBlock::Kind::kBullet;
      b.text = trim(line.substr(2));
    } else if (line.front() == '|' && i + 1 < lines.size() && is_separator(cells_of(lines[i + 1]))) {
      b.kind = MarkdownBlock::Kind::kTable;
      b.header = cells_of(line);
      for (const auto& sep : cells_of(lines[i + 1])) b.right_aligned.push_back(sep.back() == ':' && sep.front() != ':');
      i += 2;
      for (; i < lines.size() && !trim(lines[i]).empty() && trim(lines[i]).front() == '|'; ++i) {
        auto row = cells_of(lines[i]);
        row.resize(b.header.size());  // a short row gets empty cells, a long one loses its extra
        b.rows.push_back(std::move(row));
      }
      --i;  // the loop's ++i moves past the table
    } else {
      b.kind = MarkdownBlock::Kind::kParagraph;
      b.text = line;
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

}  // namespace lmc::ui
