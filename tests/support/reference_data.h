#pragma once
// Tests that read ../shared/reference-data find it here and skip, saying why, when it is absent
// (reference-data/README.md: the files may not be copied into the project).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/build_paths.h"

namespace lmc::test {

inline std::filesystem::path reference_data_dir() {
  if (const char* env = std::getenv("LMC_REFERENCE_DATA_DIR"); env != nullptr && *env != '\0') return env;
  return default_reference_dir();
}

inline std::filesystem::path reference_file(const std::string& relative) {
  return reference_data_dir() / relative;
}

inline std::filesystem::path asset_file(const std::string& relative) {
  return test_assets_dir() / relative;
}

// A fresh, empty folder for one test's files. The process id keeps test processes that run at the
// same time (ctest runs each binary in shards, in parallel) out of each other's folders.
inline std::filesystem::path scratch_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("lmc_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lmc::test

// Skips the current test with a message naming the missing file.
#define LMC_REQUIRE_REFERENCE_FILE(path)                                                       \
  do {                                                                                         \
    if (!std::filesystem::exists(path)) {                                                      \
      GTEST_SKIP() << "reference data not found at " << (path)                                 \
                   << " (../shared/reference-data is absent; this check needs it)";            \
    }                                                                                          \
  } while (0)
