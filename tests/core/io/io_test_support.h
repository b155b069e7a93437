#pragma once
// Shared helpers for the recording/TRC tests: fixture paths and "this call fails with an
// lmc::Error at file:line:column".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "core/common/error.h"
#include "tests/support/build_paths.h"

namespace lmc::test {

inline std::filesystem::path io_fixture(const std::string& name) {
  return source_dir() / "tests" / "fixtures" / "io" / name;
}

// Runs `f`, expects an lmc::Error naming `file` (in the message and the location), `line` and
// `column` (0 = not checked), and containing `fragment`.
inline void expect_error_at(const std::function<void()>& f, const std::string& file, long line, long column,
                            const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "expected an lmc::Error about " << fragment;
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, file);
    EXPECT_THAT(e.what(), ::testing::HasSubstr(file));
    EXPECT_EQ(e.where().line, line) << e.what();
    if (column > 0) {
      EXPECT_EQ(e.where().column, column) << e.what();
    }
    EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment));
  }
}

// Bitwise-equal doubles, with NaN equal to NaN (round trips must be exact, incl. -0.0).
inline bool same_double(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b && std::signbit(a) == std::signbit(b);
}

}  // namespace lmc::test
