#include "core/figures/xml_text.h"

#include <gtest/gtest.h>

#include <string>

namespace lmc::figures::xml_text_test {

TEST(FiguresXmlText, EscapesMarkupCharacters) {
  EXPECT_EQ(xml_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&apos;");
  EXPECT_EQ(xml_escape("plain"), "plain");
}

TEST(FiguresXmlText, KeepsValidUtf8AndReplacesWhatIsNot) {
  EXPECT_EQ(xml_escape("angle (\xC2\xB0)"), "angle (\xC2\xB0)");  // °
  EXPECT_EQ(xml_escape("Bland\xE2\x80\x93"
                       "Altman"),
            "Bland\xE2\x80\x93"
            "Altman");                                                    // en dash
  EXPECT_EQ(xml_escape("a\xFFz"), "a\xEF\xBF\xBDz");                      // not UTF-8
  EXPECT_EQ(xml_escape("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");          // overlong '/'
  EXPECT_EQ(xml_escape("cut \xE2\x80"), "cut \xEF\xBF\xBD\xEF\xBF\xBD");  // truncated
}

TEST(FiguresXmlText, DropsControlCharactersAndFlattensLineBreaks) {
  EXPECT_EQ(xml_escape(std::string("a\x01"
                                   "b\0c",
                                   5)),
            "abc");
  EXPECT_EQ(xml_escape("two\nlines\tand\rtab"), "two lines and tab");
}

}  // namespace lmc::figures::xml_text_test
