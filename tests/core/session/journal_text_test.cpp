// The session journal read from text, as reopening a session does (parse_journal_text, then
// state_from_journal): findings of the session_journal fuzz target, each answered with a message
// that names the journal line and the field.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "core/session/session_folder.h"
#include "core/session/session_journal.h"

namespace journal_text_test {

std::string error_of(const std::string& text) {
  try {
    (void)lmc::state_from_journal(lmc::parse_journal_text(text, "journal.jsonl"), "journal.jsonl");
  } catch (const lmc::Error& e) {
    return e.what();
  }
  return {};
}

TEST(JournalText, ASessionCreatedEventWithoutItsSetupNamesLineAndField) {
  // Found by the fuzzer: the setup was read with the JSON library's own at(), whose exception text
  // ("key 'setup' not found") is not a message for a person and escaped as another exception type.
  const std::string what = error_of(R"({"seq": 1, "type": "session_created", "s%tup": {}})"
                                    "\n");
  EXPECT_NE(what.find("journal.jsonl:1"), std::string::npos) << what;
  EXPECT_NE(what.find("/setup"), std::string::npos) << what;
}

TEST(JournalText, ACutLastLineIsDroppedWithAWarningAndABrokenMiddleLineIsAnError) {
  const auto cut = lmc::parse_journal_text("{\"type\": \"note\"}\n{\"type\": \"no", "j");
  EXPECT_TRUE(cut.cut_last_line);
  EXPECT_EQ(cut.events.size(), 1u);
  EXPECT_EQ(cut.complete_bytes, 17u);
  EXPECT_NE(error_of("{\"type\": \"note\"}\nnot json\n{}\n").find("journal.jsonl:2"), std::string::npos);
  EXPECT_NE(error_of("").find("no complete line"), std::string::npos);
}

}  // namespace journal_text_test
