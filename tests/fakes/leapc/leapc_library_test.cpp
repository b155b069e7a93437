// Finding LeapC at run time (devices/leapc/leapc_library.h): the places in their order under a
// scratch root, every place and why it failed when nothing is installed, a named library as the
// only one tried, a major version the backend was not written for refused, and a library
// installed after a failed search found by the next one (the workbench's Reconnect).
#include <cstdlib>

#include <filesystem>
#include <string>
#include "tests/support/env_var.h"

#include <gtest/gtest.h>

#include "devices/leapc/leapc_library.h"
#include "fake_leapc.h"
#include "tests/support/scratch_dir.h"

namespace lmc::devices {
namespace {

namespace fs = std::filesystem;

// The test binary names the double with LMC_LEAPC_LIBRARY (leapc_test_env.cpp); these tests search
// the known places in a scratch root instead, and put everything back afterwards.
class LeapcLibrarySearch : public ::testing::Test {
 protected:
  void SetUp() override {
    named_ = std::getenv("LMC_LEAPC_LIBRARY");
    lmc::test::unset_env("LMC_LEAPC_LIBRARY");
    lmc::test::set_env("LMC_LEAPC_SEARCH_ROOT", root_.string().c_str());
    fake_leapc::reset();
  }
  void TearDown() override {
    lmc::test::unset_env("LMC_LEAPC_SEARCH_ROOT");
    lmc::test::set_env("LMC_LEAPC_LIBRARY", named_.c_str());
    set_leapc_library_path("");
    fake_leapc::reset();
  }
  // Copies the double to `path` under the root, as a package would install the library.
  std::string install(const std::string& path) {
    const fs::path to = root_.string() + path;
    fs::create_directories(to.parent_path());
    fs::copy_file(named_, to, fs::copy_options::overwrite_existing);
    return to.string();
  }
  fs::path root_ = lmc::test::fresh_test_dir("leapc_library");
  std::string named_;
};

#ifdef _WIN32
// Windows: Ultraleap's installer's two folders under Program Files, the SDK's first; under a
// search root the root stands in for the drive.
constexpr const char* kSdkPlace = "/Program Files/Ultraleap/LeapSDK/lib/x64/LeapC.dll";
constexpr const char* kSdkWhat = "Ultraleap SDK (Windows installer)";
constexpr const char* kServicePlace = "/Program Files/Ultraleap/TrackingService/bin/LeapC.dll";

TEST_F(LeapcLibrarySearch, KnownPlacesAreTriedInTheirDocumentedOrderUnderTheSearchRoot) {
  const auto places = leapc_known_places();
  ASSERT_EQ(places.size(), 2U);
  EXPECT_EQ(places[0].path, root_.string() + kSdkPlace);
  EXPECT_EQ(places[0].what, kSdkWhat);
  EXPECT_EQ(places[1].path, root_.string() + kServicePlace);
}

TEST_F(LeapcLibrarySearch, TheSdkIsPreferredToTheServiceFolderWhenBothAreInstalled) {
  install(kServicePlace);
  const std::string sdk = install(kSdkPlace);
  const LeapcSearchResult r = find_leapc();
  ASSERT_TRUE(r.library) << r.failure_text();
  EXPECT_EQ(r.library->path, sdk);
  EXPECT_EQ(r.library->what, kSdkWhat);
}
#else
// Linux: the packages' folders and the SDK tarball's.
constexpr const char* kSdkPlace = "/opt/ultraleap/LeapSDK/lib/libLeapC.so.5";
constexpr const char* kSdkWhat = "Ultraleap SDK tarball";

TEST_F(LeapcLibrarySearch, KnownPlacesAreTriedInTheirDocumentedOrderUnderTheSearchRoot) {
  const auto places = leapc_known_places();
  ASSERT_GE(places.size(), 6U);
  const std::string root = root_.string();
  for (const auto& p : places) EXPECT_EQ(p.path.rfind(root, 0), 0U) << p.path;
  auto index_of = [&](const std::string& tail) {
    for (size_t i = 0; i < places.size(); ++i)
      if (places[i].path == root + tail) return static_cast<int>(i);
    return -1;
  };
  const int hyperion = index_of("/usr/lib/x86_64-linux-gnu/libLeapC.so.6");
  const int gemini_517 = index_of("/usr/lib/x86_64-linux-gnu/libLeapC.so.5");
  const int gemini_56 = index_of("/usr/lib/ultraleap-hand-tracking-service/libLeapC.so.5");
  const int tarball = index_of("/opt/ultraleap/LeapSDK/lib/libLeapC.so.5");
  ASSERT_GE(hyperion, 0);
  EXPECT_LT(hyperion, gemini_517);
  EXPECT_LT(gemini_517, gemini_56);
  EXPECT_LT(gemini_56, tarball);
}
#endif

TEST_F(LeapcLibrarySearch, NothingInstalledSaysEveryPlaceTriedAndWhy) {
  const LeapcSearchResult r = find_leapc();
  ASSERT_FALSE(r.library);
  // Under a search root the dynamic loader's own search is skipped: the known places only.
  ASSERT_EQ(r.tried.size(), leapc_known_places().size());
  const std::string text = r.failure_text();
  for (const auto& t : r.tried) {
    EXPECT_EQ(t.outcome, "not there") << t.path;
    EXPECT_NE(text.find(t.path), std::string::npos) << t.path;
  }
  EXPECT_NE(text.find("--leapc-library"), std::string::npos) << text;
}

TEST_F(LeapcLibrarySearch, ALibraryInstalledAfterAFailedSearchIsFoundByTheNext) {
  ASSERT_FALSE(find_leapc().library);
  const std::string path = install(kSdkPlace);
  const LeapcSearchResult r = find_leapc();
  ASSERT_TRUE(r.library) << r.failure_text();
  EXPECT_EQ(r.library->path, path);
  EXPECT_EQ(r.library->what, kSdkWhat);
  ASSERT_TRUE(r.library->version);
  EXPECT_EQ(leapc_version_text(*r.library->version), "5.6.1");
  EXPECT_NE(leapc_library_text(*r.library).find("LeapC 5.6.1 from " + path), std::string::npos);
}

#ifndef _WIN32
TEST_F(LeapcLibrarySearch, HyperionIsPreferredToGeminiWhenBothAreInstalled) {
  install("/usr/lib/ultraleap-hand-tracking-service/libLeapC.so.5");
  const std::string hyperion = install("/usr/lib/x86_64-linux-gnu/libLeapC.so.6");
  const LeapcSearchResult r = find_leapc();
  ASSERT_TRUE(r.library) << r.failure_text();
  EXPECT_EQ(r.library->path, hyperion);
  EXPECT_EQ(r.library->what, "Hyperion 6 package");
}
#endif

TEST_F(LeapcLibrarySearch, ANamedLibraryIsTheOnlyOneTried) {
  install("/opt/ultraleap/LeapSDK/lib/libLeapC.so.5");
  set_leapc_library_path(root_.string() + "/elsewhere/libLeapC.so.5");
  LeapcSearchResult r = find_leapc();
  ASSERT_FALSE(r.library);
  ASSERT_EQ(r.tried.size(), 1U);
  EXPECT_EQ(r.tried[0].what, "--leapc-library");
  EXPECT_EQ(r.tried[0].outcome, "not there");
  set_leapc_library_path(named_);
  r = find_leapc();
  ASSERT_TRUE(r.library) << r.failure_text();
  EXPECT_EQ(r.library->path, named_);
}

TEST_F(LeapcLibrarySearch, AMajorVersionTheBackendWasNotWrittenForIsRefusedWithItsVersion) {
  set_leapc_library_path(named_);  // the double this binary is linked with: its version is scriptable
  fake_leapc::set_version(8, 0, 2);
  const LeapcSearchResult r = find_leapc();
  ASSERT_FALSE(r.library);
  ASSERT_EQ(r.tried.size(), 1U);
  EXPECT_NE(r.tried[0].outcome.find("refused: it is LeapC 8.0.2"), std::string::npos) << r.tried[0].outcome;
  EXPECT_NE(r.tried[0].outcome.find("5 (Gemini), 6 and 7 (Hyperion)"), std::string::npos) << r.tried[0].outcome;
  fake_leapc::set_version(6, 2, 0);
  EXPECT_TRUE(find_leapc().library);
  EXPECT_TRUE(leapc_major_supported(5));
  EXPECT_TRUE(leapc_major_supported(6));
  EXPECT_TRUE(leapc_major_supported(7));
  EXPECT_FALSE(leapc_major_supported(4));
  EXPECT_FALSE(leapc_major_supported(8));
}

}  // namespace
}  // namespace lmc::devices
