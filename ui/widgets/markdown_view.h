#pragma once
// A report written as Markdown (ui/model/text/markdown_blocks.h) drawn with ImGui: headings,
// bullets, wrapped paragraphs and pipe tables as real tables (numbers right-aligned as the
// separator row says), in a scrolling region.
#include <vector>

#include "ui/model/text/markdown_blocks.h"

namespace lmc::ui {

void draw_markdown_view(const char* id, const std::vector<MarkdownBlock>& blocks);

}  // namespace lmc::ui
