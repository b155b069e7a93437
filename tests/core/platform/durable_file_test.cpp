// The durable-file seam (core/platform/durable_file.h) and the atomic write on top of it, on both
// systems: the same assertions run on Linux and, cross-built, under Wine.
#include <gtest/gtest.h>

#ifdef _WIN32
#include <windows.h>
#endif

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/io/atomic_write.h"
#include "core/platform/durable_file.h"
#include "core/session/session_journal.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/wine.h"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A folder a lab PC really has: spaces and a user name beyond ASCII (built from UTF-8 so the
// test does not depend on the compiler's source character set).
fs::path awkward_dir() {
  const auto dir = lmc::test::scratch_dir("durable") / fs::path(u8"Dr M\u00fcller") / "One Drive";
  fs::create_directories(dir);
  return dir;
}

int leftover_temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().front() == '.') ++n;
  return n;
}

}  // namespace

TEST(DurableFile, AtomicWriteReplacesAFileInAFolderWithSpacesAndUmlauts) {
  const auto dir = awkward_dir();
  const auto target = dir / fs::path(u8"Sitzung \u00e4.json");
  lmc::write_file_atomically(target, "first");
  lmc::write_file_atomically(target, "second, longer");
  EXPECT_EQ(slurp(target), "second, longer");
  EXPECT_EQ(leftover_temporaries(dir), 0);
}

TEST(DurableFile, ModesRefuseWhatTheyPromiseNotToDo) {
  const auto dir = awkward_dir();
  const auto path = dir / "journal.jsonl";
  EXPECT_THROW(lmc::platform::DurableFile(path, lmc::platform::OpenMode::append), lmc::Error);  // must exist
  {
    lmc::platform::DurableFile f(path, lmc::platform::OpenMode::append_new);
    ASSERT_TRUE(f.write("one\n"));
    ASSERT_TRUE(f.sync());
    EXPECT_EQ(f.bytes_written(), 4u);
    EXPECT_FALSE(f.deleted_while_open());
  }
  EXPECT_THROW(lmc::platform::DurableFile(path, lmc::platform::OpenMode::append_new), lmc::Error);  // exists
  {
    lmc::platform::DurableFile f(path, lmc::platform::OpenMode::append);
    ASSERT_TRUE(f.write("two\n"));
    ASSERT_TRUE(f.close());
  }
  EXPECT_EQ(slurp(path), "one\ntwo\n");
  {
    lmc::platform::DurableFile f(path, lmc::platform::OpenMode::truncate);
    ASSERT_TRUE(f.write("x"));
  }
  EXPECT_EQ(slurp(path), "x");
}

TEST(DurableFile, AFileDeletedWhileOpenIsNoticed) {
  const auto path = awkward_dir() / "gone.raw.txt";
  lmc::platform::DurableFile f(path, lmc::platform::OpenMode::truncate);
  ASSERT_TRUE(f.write("row\n"));
  fs::remove(path);
  if (lmc::test::running_under_wine())
    GTEST_SKIP() << "Wine keeps a file deleted while open in its folder until the last handle closes and reports "
                    "no pending delete for it; Windows reports it (FILE_STANDARD_INFO.DeletePending), Linux by the "
                    "link count";
  EXPECT_TRUE(f.deleted_while_open());
}

TEST(DurableFile, AFolderInTheWayFailsTheRenameByName) {
  const auto dir = awkward_dir();
  fs::create_directories(dir / "out.txt");
  try {
    lmc::write_file_atomically(dir / "out.txt", "data");
    FAIL() << "a folder in the way must fail the write";
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find("rename failed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("out.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(leftover_temporaries(dir), 0);
}

TEST(DurableFile, JournalReadsLinesEndedByCrLf) {
  // A journal copied through a Windows editor or a git checkout with autocrlf ends its lines in
  // CR LF; JSON counts the CR as white space, so nothing is lost.
  const auto j = lmc::parse_journal_text("{\"seq\":1}\r\n{\"seq\":2}\r\n", "journal.jsonl");
  ASSERT_EQ(j.events.size(), 2u);
  EXPECT_EQ(j.events[1]["seq"], 2);
  EXPECT_FALSE(j.cut_last_line);
}

TEST(DurableFile, AFileHeldOpenByAnotherProgramIsNamedAndNothingIsLost) {
#ifdef _WIN32
  const auto dir = awkward_dir();
  const auto target = dir / "trials.csv";
  lmc::write_file_atomically(target, "old");
  // What a spreadsheet does with a CSV it shows: open it and share nothing.
  const HANDLE held =
      CreateFileW(target.c_str(), GENERIC_READ, 0, nullptr, OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
  ASSERT_NE(held, INVALID_HANDLE_VALUE);
  try {
    lmc::write_file_atomically(target, "new");
    CloseHandle(held);
    FAIL() << "a file another program holds must not be replaced";
  } catch (const lmc::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("trials.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("close it"), std::string::npos) << what;
  }
  CloseHandle(held);
  EXPECT_EQ(slurp(target), "old");  // untouched
  EXPECT_EQ(leftover_temporaries(dir), 0);
  lmc::write_file_atomically(target, "new");  // once closed, the retry succeeds
  EXPECT_EQ(slurp(target), "new");
#else
  GTEST_SKIP() << "Linux lets a file be replaced while another program has it open: nothing to refuse";
#endif
}

TEST(DurableFile, PathsWithBackslashesAndDriveLetters) {
#ifdef _WIN32
  const auto dir = awkward_dir();
  // The same folder spelled with backslashes and its absolute drive-letter form.
  const std::wstring spelled = fs::absolute(dir).make_preferred().wstring() + L"\\sub\\file.txt";
  ASSERT_EQ(spelled[1], L':');
  fs::create_directories(dir / "sub");
  lmc::write_file_atomically(fs::path(spelled), "via backslashes");
  EXPECT_EQ(slurp(dir / "sub/file.txt"), "via backslashes");
#else
  GTEST_SKIP() << "drive letters and backslash separators are Windows' spelling of a path";
#endif
}
