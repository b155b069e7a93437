#pragma once
// Folders for one test's files under the system's temporary folder. Each is removed when the test
// program ends with every test passed; after a failure they stay for inspection and the program
// says where. (Before, every run of the suite left about a hundred folders behind in /tmp.)
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "core/platform/process.h"

namespace lmc::test {

namespace detail {

class ScratchRegistry {
 public:
  static ScratchRegistry& instance() {
    static ScratchRegistry registry;
    return registry;
  }

  void add(const std::filesystem::path& dir) {
    const std::lock_guard lock(mutex_);
    dirs_.push_back(dir);
  }

  ScratchRegistry(const ScratchRegistry&) = delete;
  ScratchRegistry& operator=(const ScratchRegistry&) = delete;

  ~ScratchRegistry() {
    // A forked child that returns through exit() must not remove its parent's folders.
    if (platform::current_process_id() != owner_) return;
    const bool passed = ::testing::UnitTest::GetInstance()->Passed();
    for (const auto& dir : dirs_) {
      if (passed) {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
      } else if (std::filesystem::exists(dir)) {
        std::fprintf(stderr, "kept for inspection (a test failed): %s\n", dir.string().c_str());
      }
    }
  }

 private:
  // GoogleTest's UnitTest made first (a folder may be asked for during static initialisation):
  // statics are destroyed in reverse order, so it outlives this registry's verdict.
  ScratchRegistry() { (void)::testing::UnitTest::GetInstance(); }

  int owner_ = platform::current_process_id();
  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

}  // namespace detail

// Removes `path` (a folder or a file) when the program ends with every test passed.
inline void remove_at_exit(const std::filesystem::path& path) {
  detail::ScratchRegistry::instance().add(path);
}

// A fresh, empty folder named for `name`. The process id keeps test processes that run at the
// same time (ctest runs each binary in shards, in parallel) out of each other's folders.
inline std::filesystem::path scratch_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("lmc_test_" + name + "_" + std::to_string(platform::current_process_id()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  remove_at_exit(dir);
  return dir;
}

// A fresh folder path (not yet created) named for `name` and the running test, for code that
// creates its own folder and refuses one that exists.
inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() / ("lmc_" + name + "_" + std::string(info->name()) + "_" +
                                                             std::to_string(platform::current_process_id()));
  std::filesystem::remove_all(dir);
  remove_at_exit(dir);
  return dir;
}

}  // namespace lmc::test
