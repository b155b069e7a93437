// The session lock and the locked state file (core/platform/file_lock.h) on both systems.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/platform/file_lock.h"
#include "core/platform/process.h"
#include "tests/support/scratch_dir.h"

namespace fs = std::filesystem;

TEST(FileLock, ASecondTakerIsRefusedAndToldWhoHoldsIt) {
  const auto path = lmc::test::scratch_dir("file_lock") / ".lock";
  const std::string me = std::to_string(lmc::platform::current_process_id());
  std::string holder;
  lmc::platform::FileLock first = lmc::platform::FileLock::take(path, me, &holder);
  ASSERT_TRUE(first.held());
  EXPECT_TRUE(lmc::platform::file_lock_is_held(path));
  lmc::platform::FileLock second = lmc::platform::FileLock::take(path, "other", &holder);
  EXPECT_FALSE(second.held());
  EXPECT_EQ(holder, me);  // readable though locked: the lock sits past the text
  first.release();
  EXPECT_FALSE(lmc::platform::file_lock_is_held(path));
  lmc::platform::FileLock third = lmc::platform::FileLock::take(path, "third", &holder);
  EXPECT_TRUE(third.held());
}

TEST(FileLock, AHolderThatRemovesItsFileLetsTheNextTakeIt) {
  // A session's clean close removes .lock while holding it.
  const auto path = lmc::test::scratch_dir("file_lock_removed") / ".lock";
  std::string holder;
  lmc::platform::FileLock first = lmc::platform::FileLock::take(path, "1", &holder);
  ASSERT_TRUE(first.held());
  fs::remove(path);
  first.release();
  lmc::platform::FileLock next = lmc::platform::FileLock::take(path, "2", &holder);
  EXPECT_TRUE(next.held());
  EXPECT_FALSE(lmc::platform::file_lock_is_held(path / "absent"));
}

TEST(FileLock, LockedFileReadsAndReplacesItsText) {
  const auto path = lmc::test::scratch_dir("locked_file") / "vicon-packet-id";
  std::string text;
  {
    lmc::platform::LockedFile f = lmc::platform::LockedFile::open(path, &text);
    EXPECT_EQ(text, "");
    std::string why;
    ASSERT_TRUE(f.replace_text("41\n", &why)) << why;
  }
  {
    lmc::platform::LockedFile f = lmc::platform::LockedFile::open(path, &text);
    EXPECT_EQ(text, "41\n");
    std::string why;
    ASSERT_TRUE(f.replace_text("7\n", &why)) << why;  // shorter: the old tail must go
  }
  lmc::platform::LockedFile f = lmc::platform::LockedFile::open(path, &text);
  EXPECT_EQ(text, "7\n");
}
