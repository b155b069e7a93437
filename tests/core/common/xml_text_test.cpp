#include "core/common/xml_text.h"

#include <gtest/gtest.h>

#include <string>

namespace lmc::xml_text_test {

TEST(XmlText, EscapesMarkupCharacters) {
  EXPECT_EQ(xml_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&apos;");
  EXPECT_EQ(xml_escape("plain"), "plain");
}

TEST(XmlText, KeepsValidUtf8AndReplacesWhatIsNot) {
  EXPECT_EQ(xml_escape("angle (\xC2\xB0)"), "angle (\xC2\xB0)");  // °
  EXPECT_EQ(xml_escape("Bland\xE2\x80\x93"
                       "Altman"),
            "Bland\xE2\x80\x93"
            "Altman");                                                    // en dash
  EXPECT_EQ(xml_escape("a\xFFz"), "a\xEF\xBF\xBDz");                      // not UTF-8
  EXPECT_EQ(xml_escape("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");          // overlong '/'
  EXPECT_EQ(xml_escape("cut \xE2\x80"), "cut \xEF\xBF\xBD\xEF\xBF\xBD");  // truncated
}

TEST(XmlText, DropsControlCharactersAndFlattensLineBreaks) {
  EXPECT_EQ(xml_escape(std::string("a\x01"
                                   "b\0c",
                                   5)),
            "abc");
  EXPECT_EQ(xml_escape("two\nlines\tand\rtab"), "two lines and tab");
}

// The Vicon trigger's rule (devices/vicon/vicon_message.cpp): a tab stays, line breaks go, and the
// rest is the same rule.
TEST(XmlText, TheViconRuleKeepsTabsAndDropsLineBreaks) {
  EXPECT_EQ(xml_escape("two\nlines\tand\rtab", XmlBreaks::kKeepTabDropLineBreaks), "twolines\tandtab");
  EXPECT_EQ(xml_escape("<a> & \xC2\xB0 \x7F", XmlBreaks::kKeepTabDropLineBreaks), "&lt;a&gt; &amp; \xC2\xB0 \x7F");
  EXPECT_EQ(xml_escape("a\xFFz", XmlBreaks::kKeepTabDropLineBreaks), "a\xEF\xBF\xBDz");
  EXPECT_EQ(xml_escape(std::string("a\x01"
                                   "b\0c",
                                   5),
                       XmlBreaks::kKeepTabDropLineBreaks),
            "abc");
}

}  // namespace lmc::xml_text_test
