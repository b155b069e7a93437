// The Markdown subset of our reports (the Review tab's study tables): headings,
// bullets, paragraphs and pipe tables with their alignment; ragged rows are squared.
#include <gtest/gtest.h>

#include "ui/model/text/markdown_blocks.h"

namespace lmc::ui {
namespace markdown_blocks_test {  // named: test files share unity batches

TEST(MarkdownBlocks, HeadingsBulletsParagraphsAndTables) {
  const auto b = parse_markdown_blocks(
      "# Processing report\n\n80 trial(s).\n\n* Finger length: 0.28 ± 1.18 mm\n\n## Finger length (mm)\n\n"
      "| layout | n | LMC − Vicon |\n|---|---:|---:|\n| initial | 5 | 0.03 ± 0.05 |\n| optimized | 5 |\n\nafter\n");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[0].kind, MarkdownBlock::Kind::kHeading);
  EXPECT_EQ(b[0].level, 1);
  EXPECT_EQ(b[0].text, "Processing report");
  EXPECT_EQ(b[1].kind, MarkdownBlock::Kind::kParagraph);
  EXPECT_EQ(b[2].kind, MarkdownBlock::Kind::kBullet);
  EXPECT_EQ(b[2].text, "Finger length: 0.28 ± 1.18 mm");
  EXPECT_EQ(b[3].level, 2);
  ASSERT_EQ(b[4].kind, MarkdownBlock::Kind::kTable);
  EXPECT_EQ(b[4].header, (std::vector<std::string>{"layout", "n", "LMC − Vicon"}));
  EXPECT_EQ(b[4].right_aligned, (std::vector<bool>{false, true, true}));
  ASSERT_EQ(b[4].rows.size(), 2u);
  EXPECT_EQ(b[4].rows[0][2], "0.03 ± 0.05");
  EXPECT_EQ(b[4].rows[1], (std::vector<std::string>{"optimized", "5", ""}));
  EXPECT_EQ(b[5].text, "after");
}

TEST(MarkdownBlocks, APipeLineWithoutASeparatorIsAParagraph) {
  const auto b = parse_markdown_blocks("| not | a table |\nplain\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].kind, MarkdownBlock::Kind::kParagraph);
  EXPECT_TRUE(parse_markdown_blocks("").empty());
}

}  // namespace markdown_blocks_test
}  // namespace lmc::ui
