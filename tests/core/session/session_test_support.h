#pragma once
// A fresh folder per test (ctest runs tests of one binary in parallel processes).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

namespace lmc::test {

inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("lmc_" + name + "_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

}  // namespace lmc::test
