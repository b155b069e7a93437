// On Windows LeapC is found where Ultraleap's installer puts it, with no search root and no
// variable naming it: the double, built as LeapC.dll, is installed at
// C:\Program Files\Ultraleap\LeapSDK\lib\x64\LeapC.dll (Wine's C: drive is its prefix) and found
// there by the search the backend runs at every start. Built for Windows only (tests/CMakeLists.txt).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "devices/leapc/leapc_library.h"
#include "fake_leapc.h"
#include "tests/support/env_var.h"

namespace lmc::devices {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(LeapcWindowsPlace, FoundInTheUltraleapSdkFolder) {
  const char* named = std::getenv("LMC_LEAPC_LIBRARY");
  ASSERT_NE(named, nullptr) << "the test binary names the double (leapc_test_env.cpp)";
  const std::string double_path = named;
  const fs::path place = "C:/Program Files/Ultraleap/LeapSDK/lib/x64/LeapC.dll";
  // The double an earlier run put there stays (this process loads it, and Windows deletes no
  // library a process has loaded), perhaps another build's: replaced. A real LeapC there is never
  // replaced.
  if (fs::exists(place) && read_bytes(place).find(fake_leapc::kMarker) == std::string::npos)
    GTEST_SKIP() << place << " is Ultraleap's LeapC, installed on this machine: not replaced by the double";
  fs::create_directories(place.parent_path());
  fs::copy_file(double_path, place, fs::copy_options::overwrite_existing);
  lmc::test::unset_env("LMC_LEAPC_LIBRARY");
  fake_leapc::reset();
  const LeapcSearchResult found = find_leapc();
  lmc::test::set_env("LMC_LEAPC_LIBRARY", double_path.c_str());
  std::error_code ec;
  fs::remove_all("C:/Program Files/Ultraleap", ec);
  ASSERT_NE(found.library, nullptr) << found.failure_text();
  EXPECT_EQ(fs::path(found.library->path), place);
  EXPECT_EQ(found.library->what, "Ultraleap SDK (Windows installer)");
  EXPECT_EQ(found.tried.size(), 1u);
}

}  // namespace
}  // namespace lmc::devices
