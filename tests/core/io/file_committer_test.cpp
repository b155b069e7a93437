// The committer that writes a batch's outputs on a thread of its own: every file arrives whole
// and no temporary file is left, a file that cannot be written is reported with its owner and path,
// and a small memory bound makes producers wait rather than lose files.
#include <gtest/gtest.h>

#include <cerrno>
#include <string>
#include <thread>
#include <vector>

#include "core/io/file_committer.h"
#include "core/platform/system_error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/scratch_dir.h"

namespace lmc {
namespace {

using test::read_text_file;

TEST(FileCommitter, WritesEveryFileFromSeveralThreadsWhole) {
  const auto dir = test::scratch_dir("committer_whole");
  // A bound of 1 kB against files of 4 kB: every submit waits for the one before it.
  FileCommitter committer(1024);
  std::vector<std::thread> producers;
  for (int t = 0; t < 3; ++t) {
    producers.emplace_back([&, t] {
      for (int k = 0; k < 20; ++k) {
        const std::string name = "t" + std::to_string(t) + "_" + std::to_string(k) + ".txt";
        committer.submit(dir / name, std::string(4096, static_cast<char>('a' + t)) + name, "trial" + std::to_string(t));
      }
    });
  }
  for (auto& p : producers) p.join();
  EXPECT_TRUE(committer.finish().empty());
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    ++files;
    const std::string name = e.path().filename().string();
    ASSERT_EQ(name.front(), 't') << "a temporary file was left behind: " << name;
    const std::string text = read_text_file(e.path());
    ASSERT_EQ(text.size(), 4096 + name.size()) << name;
    EXPECT_EQ(text.substr(4096), name);
    EXPECT_EQ(text[0], static_cast<char>('a' + (name[1] - '0')));
  }
  EXPECT_EQ(files, 60);
}

TEST(FileCommitter, ReportsAFileThatCannotBeWrittenWithItsOwnerAndPath) {
  const auto dir = test::scratch_dir("committer_fail");
  FileCommitter committer;
  committer.submit(dir / "fine.txt", "kept\n", "Naiv_Index101");
  committer.submit(dir / "no_such_folder" / "lost.txt", "x\n", "Naiv_Index102");
  committer.submit(dir / "also_fine.txt", "kept too\n", "Naiv_Index103");
  const auto failures = committer.finish();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].owner, "Naiv_Index102");
  EXPECT_NE(failures[0].message.find("lost.txt"), std::string::npos) << failures[0].message;
  // The system's own words for a missing folder: strerror(ENOENT), or Windows' ERROR_PATH_NOT_FOUND (3).
#ifdef _WIN32
  const std::string missing = platform::system_error_text(3);
#else
  const std::string missing = platform::system_error_text(ENOENT);
#endif
  EXPECT_NE(failures[0].message.find(missing), std::string::npos) << failures[0].message;
  // The files around the failure are written all the same.
  EXPECT_EQ(read_text_file(dir / "fine.txt"), "kept\n");
  EXPECT_EQ(read_text_file(dir / "also_fine.txt"), "kept too\n");
}

TEST(FileCommitter, AFileSubmittedAfterFinishIsReportedNotDropped) {
  const auto dir = test::scratch_dir("committer_late");
  FileCommitter committer;
  EXPECT_TRUE(committer.finish().empty());
  committer.submit(dir / "late.txt", "late\n", "Opti_Wrist205");
  const auto failures = committer.finish();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].owner, "Opti_Wrist205");
  EXPECT_NE(failures[0].message.find("late.txt"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "late.txt"));
}

}  // namespace
}  // namespace lmc
