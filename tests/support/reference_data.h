#pragma once
// Tests that read the study's data folder find it here and skip, saying why, when it is absent
// (the study's files are distributed with the study and may not be copied into the project).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/build_paths.h"
#include "tests/support/scratch_dir.h"

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

}  // namespace lmc::test

// Skips the current test with a message naming the missing file.
#define LMC_REQUIRE_REFERENCE_FILE(path)                                           \
  do {                                                                             \
    if (!std::filesystem::exists(path)) {                                          \
      GTEST_SKIP() << "reference data not found at " << (path)                     \
                   << " (the study's data folder is absent; this check needs it)"; \
    }                                                                              \
  } while (0)
