#include "ui/widgets/markdown_view.h"

#include "ui/widgets/palette.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>

namespace lmc::ui {
namespace {

// The workbench font has Latin-1 (±, °, ×) but not these; reports use them.
std::string displayable(std::string text) {
  const std::pair<const char*, const char*> swaps[] = {{"\u2212", "-"},   {"\u2264", "<="}, {"\u2265", ">="},
                                                       {"\u2026", "..."}, {"\u2013", "-"},  {"\u2014", "-"},
                                                       {"\u2192", "->"}};
  for (const auto& [from, to] : swaps) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      text.replace(at, std::string(from).size(), to);
      at += std::string(to).size();
    }
  }
  return text;
}

}  // namespace

void draw_markdown_view(const char* id, const std::vector<MarkdownBlock>& blocks) {
  // A table wider than the view scrolls sideways; headings and text wrap.
  ImGui::BeginChild(id, ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  ImGui::PushTextWrapPos(0.0F);
  int table = 0;
  for (const auto& b : blocks) {
    switch (b.kind) {
      case MarkdownBlock::Kind::kHeading:
        ImGui::Spacing();
        if (b.level <= 1) {
          ImGui::TextWrapped("%s", displayable(b.text).c_str());
          ImGui::Separator();
        } else {
          ImGui::TextColored(palette::kInfo, "%s", displayable(b.text).c_str());
        }
        break;
      case MarkdownBlock::Kind::kBullet:
        ImGui::Bullet();
        ImGui::TextWrapped("%s", displayable(b.text).c_str());
        break;
      case MarkdownBlock::Kind::kParagraph:
        ImGui::TextWrapped("%s", displayable(b.text).c_str());
        break;
      case MarkdownBlock::Kind::kTable: {
        const int columns = std::max<int>(1, static_cast<int>(b.header.size()));
        const std::string table_id = "table" + std::to_string(table++);
        const ImGuiTableFlags flags =
            ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
        if (ImGui::BeginTable(table_id.c_str(), columns, flags)) {
          for (const auto& h : b.header) ImGui::TableSetupColumn(displayable(h).c_str());
          ImGui::TableHeadersRow();
          for (const auto& row : b.rows) {
            ImGui::TableNextRow();
            for (size_t c = 0; c < row.size(); ++c) {
              ImGui::TableNextColumn();
              const std::string cell = displayable(row[c]);
              if (c < b.right_aligned.size() && b.right_aligned[c]) {
                const float w = ImGui::CalcTextSize(cell.c_str()).x;
                ImGui::SetCursorPosX(ImGui::GetCursorPosX() + std::max(0.0F, ImGui::GetColumnWidth() - w - 8));
              }
              ImGui::TextUnformatted(cell.c_str());
            }
          }
          ImGui::EndTable();
        }
        break;
      }
    }
  }
  ImGui::PopTextWrapPos();
  ImGui::EndChild();
}

}  // namespace lmc::ui
