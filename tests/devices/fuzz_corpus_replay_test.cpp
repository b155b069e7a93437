// Replays every checked-in fuzz input (tests/fuzz/corpus/<target>/ and the inputs that once broke
// a reader, tests/fuzz/regressions/<target>/) through the same target functions the libFuzzer
// program drives, in the ordinary ASan/UBSan test build: a reader that regresses on any of them
// fails here even where clang is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_targets.h"
#include "tests/support/build_paths.h"

namespace fuzz_corpus_replay_test {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_in(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Replayed {
  int ran = 0;
  int accepted = 0;  // read without an lmc::Error
};

// Runs each file; an exception other than lmc::Error fails the test naming the input.
Replayed replay(const lmc::fuzz::Target& target, const std::vector<fs::path>& files) {
  Replayed r;
  for (const auto& f : files) {
    try {
      if (lmc::fuzz::run_one(target, bytes_of(f))) ++r.accepted;
    } catch (const std::exception& e) {
      ADD_FAILURE() << target.name << " on " << f << ": " << e.what()
                    << " (a reader must answer bad input with lmc::Error)";
    }
    ++r.ran;
  }
  return r;
}

const fs::path kFuzzDir = lmc::test::source_dir() / "tests" / "fuzz";

TEST(FuzzCorpusReplay, EveryTargetHasASeedCorpusAndReadsItWithoutAForeignException) {
  ASSERT_GE(lmc::fuzz::targets().size(), 11u);
  for (const auto& t : lmc::fuzz::targets()) {
    const auto files = inputs_in(kFuzzDir / "corpus" / t.name);
    EXPECT_GE(files.size(), 3u) << t.name << ": seed its corpus in tests/fuzz/corpus/" << t.name;
    const Replayed r = replay(t, files);
    EXPECT_EQ(r.ran, static_cast<int>(files.size()));
    // A corpus the reader refuses whole only ever fuzzes its first check.
    EXPECT_GE(r.accepted, 1) << t.name << ": no seed in tests/fuzz/corpus/" << t.name << " is read without an error";
  }
}

TEST(FuzzCorpusReplay, EveryInputThatOnceBrokeAReaderIsAnsweredWithAMessage) {
  int total = 0;
  for (const auto& t : lmc::fuzz::targets()) total += replay(t, inputs_in(kFuzzDir / "regressions" / t.name)).ran;
  // The folder keeps every finding's input; it is never emptied.
  EXPECT_GE(total, 1);
}

TEST(FuzzCorpusReplay, EachRegressionFolderNamesATarget) {
  for (const auto& dir : fs::directory_iterator(kFuzzDir / "regressions"))
    EXPECT_NE(lmc::fuzz::find_target(dir.path().filename().string()), nullptr)
        << dir.path() << " is not the name of a fuzz target";
}

}  // namespace fuzz_corpus_replay_test
