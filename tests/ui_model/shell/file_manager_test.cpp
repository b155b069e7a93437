// Opening a folder in the desktop's file manager: the opener gets the folder as one argument (spaces
// and quotes untouched) and runs detached; a missing folder or a missing opener is an error in words.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "tests/support/cli_runner.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/shell/file_manager.h"

namespace lmc::ui {
namespace file_manager_test {  // named: test files share unity batches

namespace fs = std::filesystem;

TEST(FileManager, StartsTheOpenerWithTheFolderAsOneArgument) {
  const fs::path dir = test::scratch_dir("file_manager");
  const fs::path folder = dir / "an export's \"folder\" $HOME";
  fs::create_directories(folder);
  // A stand-in for xdg-open that writes what it was given.
  const fs::path opener = dir / "fake-opener";
  // It writes beside itself and renames, so the file appears whole.
  std::ofstream(opener) << "#!/bin/sh\nd=$(dirname \"$0\")\nprintf '%s|%s' \"$#\" \"$1\" > \"$d/opened.tmp\" && mv "
                           "\"$d/opened.tmp\" \"$d/opened.txt\"\n";
  fs::permissions(opener, fs::perms::owner_all);
  std::string error;
  ASSERT_TRUE(open_in_file_manager(folder, &error, opener.string())) << error;
  const fs::path seen = dir / "opened.txt";
  for (int i = 0; i < 500 && !fs::exists(seen); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(test::read_text_file(seen), "1|" + folder.string());
}

TEST(FileManager, AMissingFolderOrOpenerIsAnErrorInWords) {
  const fs::path dir = test::scratch_dir("file_manager_errors");
  std::string error;
  EXPECT_FALSE(open_in_file_manager(dir / "gone", &error, "true"));
  EXPECT_EQ(error, "no such folder: " + (dir / "gone").string());
  EXPECT_FALSE(open_in_file_manager(dir, &error, "lmc-no-such-opener"));
  EXPECT_EQ(error, "lmc-no-such-opener is not installed");
}

}  // namespace file_manager_test
}  // namespace lmc::ui
